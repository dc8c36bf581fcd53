// Wires between the machine's devices (docs/network.md, "Wires"): an ST program's process image
// outputs drive a simulated EPOS2's inputs, and an EPOS2's outputs reach the program's inputs,
// sampled every millisecond of machine time.
#include "compile_program.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"
#include "eposp/drives/escon2/escon2_drive.hpp"

#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;

constexpr const char* kProgram = R"(
    PROGRAM Main
    VAR
        lamp AT %QX0.0 : BOOL;
        volts AT %QW16 : INT;
        ready AT %IX1.2 : BOOL;
        echo AT %IW20 : INT;
        seen_ready : BOOL;
        seen_echo : INT;
        cycles : DINT;
    END_VAR
    cycles := cycles + 1;
    lamp := cycles >= 50;
    volts := SEL(cycles >= 50, 0, -2500);
    seen_ready := ready;
    seen_echo := echo;
    END_PROGRAM
    PROGRAM OnReady
    VAR_EXTERNAL edges : DINT; END_VAR
    edges := edges + 1;
    END_PROGRAM
    VAR_GLOBAL edges : DINT; END_VAR
    CONFIGURATION C RESOURCE R ON EPOS_P
        TASK Cyclic (INTERVAL := T#1ms, PRIORITY := 1);
        {attribute 'event' := 'input %IX1.2'}
        TASK ReadyRises (PRIORITY := 0);
        PROGRAM P WITH Cyclic : Main;
        PROGRAM E WITH ReadyRises : OnReady;
    END_RESOURCE END_CONFIGURATION)";

constexpr std::string_view kNetwork = R"(slaves:
  - {node: 2}
wires:
  - {from: "%QX0.0", to: node 2 digital input 3}
  - {from: "%QW16", to: node 2 analog input 1}
  - {from: internal digital output 1, to: "%IX1.2"}
  - {from: "%QW16", to: "%IW20"}
)";

class SignalWiresTest : public testing::Test {
protected:
    void SetUp() override {
        auto network = parse_network_file(kNetwork, "net.yaml");
        ASSERT_TRUE(network) << network.error();
        device.add_network(*network);
        ASSERT_FALSE(device.plc().load(compile_program(kProgram)));
        ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
    }

    drives::epos2::Epos2Drive& slave() { return *device.simulated_slaves().front(); }
    std::string value_of(const std::string& name) { return *device.plc().value_of("P." + name); }

    EposP device;
};

TEST_F(SignalWiresTest, ProgramOutputsDriveTheSlavesInputs) {
    device.loop().run_for(20ms);
    EXPECT_FALSE(slave().digital_input(3));
    device.loop().run_for(100ms);
    EXPECT_TRUE(slave().digital_input(3));
    // 8.2.63: the analog input's voltage in mV, as the drive measures it each control period.
    EXPECT_EQ(slave().objects().get_as<std::int16_t>(0x207C, 1), -2500);
}

TEST_F(SignalWiresTest, ASlaveOutputReachesTheProgramsInput) {
    device.loop().run_for(20ms);
    EXPECT_EQ(value_of("seen_ready"), "FALSE");
    // 8.2.59: output 1 is general purpose A (bit 15) by default, shown once the mask has it.
    auto& internal = device.internal_drive().objects();
    internal.set_as<std::uint16_t>(0x2078, 2, 0x8000);
    internal.set_as<std::uint16_t>(0x2078, 1, 0x8000);
    device.loop().run_for(10ms);
    EXPECT_EQ(value_of("seen_ready"), "TRUE");
    // Through the DS-405 object that holds the byte, as an RPDO would write it: 0xA000 sub 2
    // is %IB1 (docs/runtime.md), and the input event saw the rising edge.
    EXPECT_EQ(device.objects().get_as<std::int8_t>(0xA000, 2), 0x04);
    EXPECT_EQ(*device.plc().value_of("edges"), "1");
}

TEST_F(SignalWiresTest, AWordCarriesMillivoltsAsAnInt) {
    device.loop().run_for(120ms);
    EXPECT_EQ(value_of("seen_echo"), "-2500");
    EXPECT_EQ(device.objects().get_as<std::int16_t>(0xA0C0, 5), -2500); // %IW20: 0xA0C0 sub 5
}

// Issue 20: an ST program runs an ESCON2 axis in I/O Velocity Mode through wired outputs (drive
// enable on digital input 3, the velocity set value as a voltage on analog input 1), reads its
// ready output back, and the machine's negative limit switch on digital input 4 stops it.
constexpr const char* kConveyorProgram = R"(
    PROGRAM Conveyor
    VAR
        enable AT %QX0.0 : BOOL;
        speed AT %QW16 : INT;  (* mV: -10 V .. 10 V is -2000 .. 2000 rpm *)
        ready AT %IX0.0 : BOOL;
        was_ready, fault_seen : BOOL;
    END_VAR
    enable := TRUE;
    speed := 5000;
    was_ready := was_ready OR ready;
    fault_seen := was_ready AND NOT ready;
    END_PROGRAM
    CONFIGURATION C RESOURCE R ON EPOS_P
        TASK Cyclic (INTERVAL := T#1ms, PRIORITY := 1);
        PROGRAM P WITH Cyclic : Conveyor;
    END_RESOURCE END_CONFIGURATION)";

constexpr std::string_view kConveyorNetwork = R"(escon2:
  - name: conveyor
    hardware: Module 60/30
    parameters:
      - {index: 0x3142, sub: 3, value: 27}    # digital input 3: drive enable
      - {index: 0x3142, sub: 4, value: 0}     # digital input 4: negative limit switch
      - {index: 0x3161, sub: 1, value: 9}     # analog input 1: velocity set value
      - {index: 0x31B0, sub: 2, value: -2000} #   -10 V: -2000 rpm
      - {index: 0x31B0, sub: 4, value: 2000}  #   +10 V: 2000 rpm
      - {index: 0x3151, sub: 1, value: 25}    # digital output 1: ready / fault
wires:
  - {from: "%QX0.0", to: escon2 conveyor digital input 3}
  - {from: "%QW16", to: escon2 conveyor analog input 1}
  - {from: escon2 conveyor digital output 1, to: "%IX0.0"}
)";

TEST(SignalWiresEscon2, ProgramRunsAnEscon2AxisThatTheLimitSwitchStops) {
    auto network = parse_network_file(kConveyorNetwork, "net.yaml");
    ASSERT_TRUE(network) << network.error();
    EposP device;
    device.add_network(*network);
    ASSERT_FALSE(device.plc().load(compile_program(kConveyorProgram)));
    ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
    drives::escon2::Escon2Drive& conveyor = *device.escon2("conveyor");
    device.loop().run_for(500ms);
    // 5 V of 10 V for 2000 rpm, reached along the profile acceleration.
    EXPECT_EQ(conveyor.objects().get_as<std::int32_t>(0x60FF, 0), 1000);
    EXPECT_NEAR(conveyor.objects().get_as<std::int32_t>(0x606C, 0), 1000, 30);
    EXPECT_EQ(*device.plc().value_of("P.was_ready"), "TRUE");
    EXPECT_EQ(*device.plc().value_of("P.fault_seen"), "FALSE");

    conveyor.set_digital_input(4, true); // the carriage reaches the negative limit switch
    device.loop().run_for(500ms);
    EXPECT_EQ(conveyor.objects().get_as<std::uint16_t>(0x603F, 0), 0x8A80); // ESCON2 FW 7.1.28
    EXPECT_NEAR(conveyor.objects().get_as<std::int32_t>(0x606C, 0), 0, 30);
    EXPECT_EQ(*device.plc().value_of("P.fault_seen"), "TRUE");
}

} // namespace
} // namespace eposp::device
