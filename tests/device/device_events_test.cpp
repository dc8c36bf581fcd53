// Event tasks released by the EPOS P's own events (docs/network.md, "Events"): each SYNC, an
// RPDO stored, a slave's EMCY, a rising edge of a process input bit.
#include "compile_program.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using testing::HasSubstr;

constexpr const char* kProgram = R"(
    VAR_GLOBAL never_sync, never_rpdo, never_emcy, never_input : BOOL; END_VAR
    PROGRAM Count
    VAR_INPUT which : INT; END_VAR
    VAR n : DINT; END_VAR
    n := n + 1;
    END_PROGRAM
    CONFIGURATION C RESOURCE R ON EPOS_P
        TASK OnSync (SINGLE := never_sync, PRIORITY := 1);
        TASK OnRpdo (SINGLE := never_rpdo, PRIORITY := 1);
        TASK OnEmcy (SINGLE := never_emcy, PRIORITY := 1);
        TASK OnInput (SINGLE := never_input, PRIORITY := 1);
        TASK Cyclic (INTERVAL := T#10ms, PRIORITY := 2);
        PROGRAM Syncs WITH OnSync : Count;
        PROGRAM Rpdos WITH OnRpdo : Count;
        PROGRAM Emcys WITH OnEmcy : Count;
        PROGRAM Inputs WITH OnInput : Count;
    END_RESOURCE END_CONFIGURATION)";

constexpr std::string_view kNetwork = R"(sync_period: 1ms
slaves:
  - {node: 1, port: internal, axis: 0}
events:
  - {task: OnSync, on: sync}
  - {task: OnRpdo, on: rpdo, port: internal, rpdo: 1}
  - {task: OnEmcy, on: emcy, node: 5}
  - {task: OnInput, on: input, input: "%IX16.2"}
)";

class DeviceEvents : public testing::Test {
protected:
    void SetUp() override {
        auto network = parse_network_file(kNetwork, "net.yaml");
        ASSERT_TRUE(network) << network.error();
        device.add_network(*network);
        ASSERT_FALSE(device.plc().load(compile_program(kProgram)));
        for (const EventBinding& event : network->events) {
            ASSERT_FALSE(device.bind_event(event));
        }
        ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
    }

    long count(const std::string& program) {
        return std::stol(*device.plc().value_of(program + ".n"));
    }

    EposP device;
};

TEST_F(DeviceEvents, EachSyncAndEachStoredRpdoReleaseTheirTasks) {
    device.loop().run_for(1s); // the internal EPOS2 booted and started at about 0.55 s
    const long syncs = count("Syncs");
    const long rpdos = count("Rpdos");
    device.loop().run_for(100ms);
    EXPECT_EQ(count("Syncs") - syncs, 100);
    EXPECT_EQ(count("Rpdos") - rpdos, 100); // the statusword PDO of every SYNC
    EXPECT_GT(rpdos, 300);
    EXPECT_EQ(count("Emcys"), 0);
    EXPECT_TRUE(device.plc().errors().empty());
}

TEST_F(DeviceEvents, AnEmcyOfTheBoundNodeReleasesItsTask) {
    device.loop().run_for(1s); // port 2's network started: its EMCY consumer listens
    auto tool = device.external_bus().connect("nodes");
    tool->send(can::Frame::data_frame(0x086, {0x10, 0x81, 0x11, 0, 0, 0, 0, 0})); // node 6
    device.loop().run_for(10ms);
    EXPECT_EQ(count("Emcys"), 0);
    tool->send(can::Frame::data_frame(0x085, {0x10, 0x81, 0x11, 0, 0, 0, 0, 0})); // node 5
    device.loop().run_for(10ms);
    EXPECT_EQ(count("Emcys"), 1);
}

TEST_F(DeviceEvents, ARisingEdgeOfTheProcessInputBitReleasesItsTask) {
    const auto write_byte = [this](std::uint8_t value) {
        // %IB16 is 0xA040 sub 1 (UNSIGNED8 inputs), as an RPDO or SDO writes it.
        ASSERT_EQ(device.objects().write(0xA040, 1, canopen::encode(value)),
                  canopen::AbortCode::None);
        device.loop().run_for(1ms);
    };
    write_byte(0x04);
    EXPECT_EQ(count("Inputs"), 1);
    write_byte(0x05); // bit 2 stays set: no edge
    EXPECT_EQ(count("Inputs"), 1);
    write_byte(0x01);
    write_byte(0x04);
    EXPECT_EQ(count("Inputs"), 2);
}

// The same events named by the program itself, on TASKs without SINGLE.
constexpr const char* kProgramWithEvents = R"(
    PROGRAM Count
    VAR n : DINT; END_VAR
    n := n + 1;
    END_PROGRAM
    CONFIGURATION C RESOURCE R ON EPOS_P
        {attribute 'event' := 'sync'}          TASK OnSync (PRIORITY := 1);
        {attribute 'event' := 'rpdo internal 1'} TASK OnRpdo (PRIORITY := 1);
        {attribute 'event' := 'emcy 5'}        TASK OnEmcy (PRIORITY := 1);
        {attribute 'event' := 'input %IX16.2'} TASK OnInput (PRIORITY := 1);
        PROGRAM Syncs WITH OnSync : Count;
        PROGRAM Rpdos WITH OnRpdo : Count;
        PROGRAM Emcys WITH OnEmcy : Count;
        PROGRAM Inputs WITH OnInput : Count;
    END_RESOURCE END_CONFIGURATION)";

class ProgramEvents : public testing::Test {
protected:
    void SetUp() override {
        auto network = parse_network_file(
            "sync_period: 1ms\nslaves:\n  - {node: 1, port: internal, axis: 0}\n", "net.yaml");
        ASSERT_TRUE(network) << network.error();
        device.add_network(*network);
        ASSERT_FALSE(device.plc().load(compile_program(kProgramWithEvents)));
        ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
    }

    long count(const std::string& program) {
        return std::stol(*device.plc().value_of(program + ".n"));
    }

    EposP device;
};

TEST_F(ProgramEvents, TheProgramsOwnSyncRpdoEmcyAndInputEventsReleaseItsTasks) {
    device.loop().run_for(1s);
    const long syncs = count("Syncs");
    const long rpdos = count("Rpdos");
    device.loop().run_for(100ms);
    EXPECT_EQ(count("Syncs") - syncs, 100);
    EXPECT_EQ(count("Rpdos") - rpdos, 100);

    auto tool = device.external_bus().connect("nodes");
    tool->send(can::Frame::data_frame(0x086, {0x10, 0x81, 0x11, 0, 0, 0, 0, 0})); // node 6
    tool->send(can::Frame::data_frame(0x085, {0x10, 0x81, 0x11, 0, 0, 0, 0, 0})); // node 5
    device.loop().run_for(10ms);
    EXPECT_EQ(count("Emcys"), 1);

    for (const std::uint8_t value : std::vector<std::uint8_t>{0x04, 0x05, 0x00, 0x04}) {
        ASSERT_EQ(device.objects().write(0xA040, 1, canopen::encode(value)),
                  canopen::AbortCode::None);
        device.loop().run_for(1ms);
    }
    EXPECT_EQ(count("Inputs"), 2);
    EXPECT_TRUE(device.plc().errors().empty());
}

TEST_F(ProgramEvents, ALoadedProgramReplacesTheEventsOfTheOldOne) {
    device.loop().run_for(1s);
    device.plc().runtime().stop();
    // The same task names, released by their SINGLE variables only, which stay FALSE.
    ASSERT_FALSE(device.plc().load(compile_program(kProgram)));
    ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
    device.loop().run_for(100ms);
    EXPECT_EQ(count("Syncs"), 0);
    EXPECT_EQ(count("Rpdos"), 0);
}

TEST(DeviceEventBinding, AnEventTheDeviceDoesNotHaveIsACompileErrorAtTheAttribute) {
    compiler::SourceManager sources;
    const compiler::FileId file = sources.add("main.st", R"(PROGRAM Count END_PROGRAM
CONFIGURATION C RESOURCE R ON EPOS_P
    {attribute 'event' := 'rpdo internal 5'} TASK T (PRIORITY := 1);
    PROGRAM P WITH T : Count;
END_RESOURCE END_CONFIGURATION)");
    compiler::Diagnostics diagnostics;
    EXPECT_FALSE(compile_program(sources, std::span(&file, 1), diagnostics));
    EXPECT_THAT(compiler::render(diagnostics, sources),
                HasSubstr("main.st:3:5: error: event 'rpdo internal 5': an rpdo event names the "
                          "RPDO: 1..32 on the CAN port, 1..4 on the internal one"));
}

TEST(DeviceEventBinding, AnImageNamingAnUnknownEventIsNotLoaded) {
    EposP device;
    vm::Image image = compile_program(kProgramWithEvents);
    image.tasks[0].event = "tuesday";
    const auto refusal = device.plc().load(image);
    ASSERT_TRUE(refusal);
    EXPECT_THAT(refusal->message, HasSubstr("task OnSync: event 'tuesday': an event is 'sync'"));
    EXPECT_TRUE(device.plc().verify(image));
}

TEST(DeviceEventBinding, ATaskThatIsMissingOrNotAnEventTaskIsRefused) {
    EposP device;
    ASSERT_FALSE(device.plc().load(compile_program(kProgram)));
    EventBinding event;
    event.task = "Nowhere";
    const auto missing = device.bind_event(event);
    ASSERT_TRUE(missing);
    EXPECT_THAT(missing->message, HasSubstr("event task Nowhere: the program has no such task"));
    event.task = "Cyclic";
    EXPECT_TRUE(device.bind_event(event));
}

} // namespace
} // namespace eposp::device
