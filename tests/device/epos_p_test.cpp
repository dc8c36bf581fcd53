// The EPOS P as a library: its two ports, the internal EPOS2 and the PLC on one virtual loop.
#include "compile_program.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/canopen/store_restore_objects.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/error_entry.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/manager/network_list.hpp"
#include "eposp/test/test_directory.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;

TEST(EposP, TheInternalEpos2BootsAsNodeOneOnPortOneOnly) {
    EposP device;
    std::vector<can::Frame> internal;
    std::vector<can::Frame> external;
    device.internal_port().on_receive([&](const can::Frame& frame) { internal.push_back(frame); });
    device.external_port().on_receive([&](const can::Frame& frame) { external.push_back(frame); });
    device.loop().run_for(10ms);

    ASSERT_FALSE(internal.empty());
    EXPECT_EQ(internal.front().id, 0x701u); // the boot-up message of node 1 (CiA 301 7.2.8.3.2)
    EXPECT_EQ(internal.front().payload().size(), 1u);
    EXPECT_EQ(internal.front().payload()[0], 0x00);
    EXPECT_EQ(device.internal_drive().node().nmt_state(), canopen::NmtState::PreOperational);
    EXPECT_TRUE(external.empty());
}

// 10.32: 0x5001 names port 2's bit rate (table 28); a new one, stored with "save", is the bus's
// rate from the next power-up on, as the stored node-ID is.
TEST(EposP, TheStoredCanBitRateAppliesAtTheNextPowerUp) {
    EposPConfig config;
    config.external_bit_rate = 500'000;
    config.parameter_file = test::test_file("parameters.bin");
    {
        EposP device(config);
        EXPECT_EQ(device.objects().get_as<std::uint16_t>(kCanBitRateIndex, 0), 2u);
        EXPECT_EQ(device.objects().write(kCanBitRateIndex, 0, canopen::encode(std::uint16_t{5})),
                  canopen::AbortCode::InvalidValue); // reserved
        ASSERT_EQ(device.objects().write(kCanBitRateIndex, 0, canopen::encode(std::uint16_t{3})),
                  canopen::AbortCode::None);
        EXPECT_EQ(device.external_bus().config().bitrate, 500'000u) << "only after a restart";
        ASSERT_EQ(device.objects().write(0x1010, 1, canopen::encode(canopen::kSaveSignature)),
                  canopen::AbortCode::None);
    }
    EposP restarted(config);
    EXPECT_EQ(restarted.external_bus().config().bitrate, 250'000u);
    EXPECT_EQ(restarted.objects().get_as<std::uint16_t>(kCanBitRateIndex, 0), 3u);
}

TEST(EposP, AutomaticBitRateDetectionKeepsTheBussRate) {
    EposPConfig config;
    config.external_bit_rate = 125'000;
    config.parameter_file = test::test_file("parameters.bin");
    {
        EposP device(config);
        ASSERT_EQ(device.objects().write(kCanBitRateIndex, 0, canopen::encode(std::uint16_t{9})),
                  canopen::AbortCode::None);
        ASSERT_EQ(device.objects().write(0x1010, 1, canopen::encode(canopen::kSaveSignature)),
                  canopen::AbortCode::None);
    }
    EXPECT_EQ(EposP(config).external_bus().config().bitrate, 125'000u);
}

// EPOS2 FW spec 8.2.42: the simulated EPOS2s on port 2 run at the EPOS P's bit rate, which their
// automatic bit rate detection (0x2001 = 9) finds and 0x200A shows as a code of table 8-81.
TEST(EposP, TheSimulatedEpos2sShowTheBitRateOfTheEposP) {
    EposPConfig config;
    config.external_bit_rate = 250'000;
    EposP device(config);
    const auto network = parse_network_file("slaves:\n  - {node: 2, axis: 1}\n", "net.yaml");
    ASSERT_TRUE(network) << network.error();
    device.add_network(*network);
    const auto& drive = device.simulated_slaves().at(0)->objects();
    EXPECT_EQ(drive.get_as<std::uint16_t>(0x200A, 0), 3u); // 250 kbit/s
}

TEST(EposP, RunsTheProgramsTasksAndTimersInTheLoopsTime) {
    EposP device;
    ASSERT_FALSE(device.plc().load(compile_program(R"(
        PROGRAM Main
        VAR scans : DINT; delay : TON; elapsed : BOOL; END_VAR
        scans := scans + 1;
        delay(IN := TRUE, PT := T#250ms);
        elapsed := delay.Q;
        END_PROGRAM)")));
    ASSERT_FALSE(device.plc().runtime().start(vm::StartMode::Cold));

    device.loop().run_for(245ms); // a task without a configuration runs every 10 ms
    EXPECT_EQ(*device.plc().value_of("Main.scans"), "25");
    EXPECT_EQ(*device.plc().value_of("Main.elapsed"), "FALSE");
    device.loop().run_for(10ms);
    EXPECT_EQ(*device.plc().value_of("Main.elapsed"), "TRUE");
    EXPECT_TRUE(device.plc().errors().empty());
}

constexpr const char* kDoubler = R"(
    PROGRAM Main
    VAR
        scans : DINT;
        input AT %ID24 : DINT;   (* 0xA1C0 sub 1 *)
        output AT %QD24 : DINT;  (* 0xA640 sub 1 *)
    END_VAR
    scans := scans + 1;
    output := input * 2;
    END_PROGRAM)";

canopen::AbortCode write_u16(EposP& device, std::uint16_t index, std::uint8_t sub,
                             std::uint16_t value) {
    return device.objects().write(index, sub, canopen::encode(value));
}

TEST(EposP, ProgramControlStartsAndStopsTheProgram) {
    EposP device;
    ASSERT_FALSE(device.plc().load(compile_program(kDoubler)));
    EXPECT_EQ(device.objects().get_as<std::uint16_t>(0x5F51, 0), 0u);

    ASSERT_EQ(write_u16(device, 0x5F51, 0, 1), canopen::AbortCode::None); // coldstart
    EXPECT_EQ(device.objects().get_as<std::uint16_t>(0x5F51, 0), 1u);
    device.loop().run_for(95ms);
    EXPECT_EQ(*device.plc().value_of("Main.scans"), "10");
    // Starting a running program is refused; stopping it is not.
    EXPECT_EQ(write_u16(device, 0x5F51, 0, 2), canopen::AbortCode::DeviceState);
    ASSERT_EQ(write_u16(device, 0x5F51, 0, 0), canopen::AbortCode::None);
    device.loop().run_for(100ms);
    EXPECT_EQ(*device.plc().value_of("Main.scans"), "10");
    EXPECT_EQ(device.objects().get_as<std::uint16_t>(0x5F51, 0), 0u);
}

TEST(EposP, ProgramControlWithoutAProgramIsRefused) {
    EposP device;
    EXPECT_EQ(write_u16(device, 0x5F51, 0, 1), canopen::AbortCode::DeviceState);
    EXPECT_EQ(write_u16(device, 0x5F51, 0, 0), canopen::AbortCode::None);
}

TEST(EposP, TheProcessImageObjectsAreThePlcsInputsAndOutputs) {
    EposP device;
    ASSERT_FALSE(device.plc().load(compile_program(kDoubler)));
    ASSERT_EQ(write_u16(device, 0x5F51, 0, 1), canopen::AbortCode::None);
    ASSERT_EQ(device.objects().write(0xA1C0, 1, canopen::encode(std::int32_t{-21})),
              canopen::AbortCode::None);
    device.loop().run_for(15ms);
    canopen::Bytes output;
    ASSERT_EQ(device.objects().read(0xA640, 1, output), canopen::AbortCode::None);
    EXPECT_EQ(canopen::decode<std::int32_t>(output), -42);
    EXPECT_EQ(device.objects().get_as<std::int32_t>(0xA640, 2), 0);
}

TEST(EposP, RestoreIsRefusedWhileTheProgramRuns) {
    EposP device;
    ASSERT_FALSE(device.plc().load(compile_program(kDoubler)));
    ASSERT_EQ(write_u16(device, 0x5F51, 0, 2), canopen::AbortCode::None); // warmstart
    EXPECT_EQ(device.objects().write(0x1011, 1, canopen::encode(canopen::kLoadSignature)),
              canopen::AbortCode::DeviceState);
    ASSERT_EQ(write_u16(device, 0x5F51, 0, 0), canopen::AbortCode::None);
    EXPECT_NE(device.objects().write(0x1011, 1, canopen::encode(canopen::kLoadSignature)),
              canopen::AbortCode::DeviceState);
}

TEST(EposP, APlcErrorGoesToTheErrorHistoryAndTheErrorRegister) {
    EposP device;
    ASSERT_FALSE(device.plc().load(compile_program(R"(
        PROGRAM Main
        VAR zero : DINT; quotient : DINT; END_VAR
        quotient := 10 / zero;
        END_PROGRAM)")));
    ASSERT_EQ(write_u16(device, 0x5F51, 0, 1), canopen::AbortCode::None);
    device.loop().run_for(15ms);

    ASSERT_FALSE(device.plc().errors().empty());
    const std::uint16_t code = device.plc().errors().front().code;
    EXPECT_EQ(device.objects().get_as<std::uint8_t>(0x1003, 0), device.plc().errors().size());
    // Table 4: no warning, port code 0 and node-ID 0 (the controller itself), the code.
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1003, 1), std::uint32_t{code});
    EXPECT_EQ(device.objects().get_as<std::uint8_t>(0x1001, 0) & 0x01, 0x01);
}

TEST(EposP, ErrorEntriesFollowTable4) {
    EXPECT_EQ((ErrorEntry{.code = 0x8130, .port = 2, .node = 5, .warning = false}.encode()),
              0x0205'8130u);
    EXPECT_EQ((ErrorEntry{.code = 0x8182, .port = 2, .node = 127, .warning = true}.encode()),
              0x827F'8182u);
}

constexpr std::uint32_t kMandatorySlave = 0x0000'000D; // slave, boot slave, mandatory (table 26)

void write_u32(EposP& device, std::uint16_t index, std::uint8_t sub, std::uint32_t value) {
    ASSERT_EQ(device.objects().write(index, sub, canopen::encode(value)), canopen::AbortCode::None)
        << std::hex << index << " sub " << int(sub);
}

/// Assigns the slave of network-list sub-index `sub` (node `node` on `port`) as mandatory,
/// expects maxon's vendor ID and watches its heartbeat at 100 ms.
void assign_mandatory(EposP& device, std::uint8_t sub, std::uint8_t port, std::uint8_t node) {
    write_u32(device, 0x1F81, sub, kMandatorySlave);
    write_u32(device, 0x1F85, sub, 0xFB);
    write_u32(device, 0x1016, sub, std::uint32_t{port} << 24 | std::uint32_t{node} << 16 | 100);
}

std::uint32_t history(EposP& device, std::uint8_t sub) {
    return device.objects().get_as<std::uint32_t>(0x1003, sub);
}

TEST(EposP, TheInternalEpos2BootsAsTheMandatorySlaveOfPortOne) {
    EposP device;
    assign_mandatory(device, kInternalSlaveSubIndex, kInternalPort, 1);
    device.boot_networks();
    device.loop().run_for(2s);

    EXPECT_TRUE(device.network(kInternalPort).report().network_started);
    EXPECT_EQ(device.objects().get_as<std::uint8_t>(0x1003, 0), 0u);
    EXPECT_EQ(device.internal_drive().node().nmt_state(), canopen::NmtState::Operational);
    // Configured to produce its heartbeat at half the consumer time.
    EXPECT_EQ(device.internal_drive().objects().get_as<std::uint16_t>(0x1017, 0), 50u);
}

TEST(EposP, VendorMismatchOfTheInternalEpos2IsInTheHistoryWithPortOne) {
    EposP device;
    assign_mandatory(device, kInternalSlaveSubIndex, kInternalPort, 1);
    write_u32(device, 0x1F85, kInternalSlaveSubIndex, 0xFC);
    device.boot_networks();
    device.loop().run_for(2s);

    EXPECT_FALSE(device.network(kInternalPort).report().network_started);
    EXPECT_EQ(history(device, 1), 0x0101'6382u); // port 1, node 1, Vendor-Id Error
    EXPECT_EQ(device.internal_drive().node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST(EposP, AMissingMandatorySlaveOnPortTwoIsNoAnswerInTheHistory) {
    EposP device;
    assign_mandatory(device, 5, kExternalPort, 5);
    device.boot_networks();
    device.loop().run_for(3s);

    EXPECT_FALSE(device.network(kExternalPort).report().network_started);
    EXPECT_EQ(history(device, 1), 0x0205'8182u); // port 2, node 5, CAN No Answer Error
    EXPECT_EQ(device.objects().get_as<std::uint8_t>(0x1001, 0) & 0x10, 0x10); // communication
}

TEST(EposP, AnEpos2OnPortTwoBootsAndStarts) {
    EposP device;
    auto port = device.external_bus().connect("epos2-2");
    drives::epos2::Epos2DriveConfig config;
    config.dictionary.node_id = 2;
    drives::epos2::Epos2Drive drive(device.loop(), *port, config);
    drive.start();
    assign_mandatory(device, 2, kExternalPort, 2);
    device.boot_networks();
    device.loop().run_for(2s);

    EXPECT_TRUE(device.network(kExternalPort).report().network_started);
    EXPECT_EQ(drive.node().nmt_state(), canopen::NmtState::Operational);
    EXPECT_EQ(device.objects().get_as<std::uint8_t>(0x1003, 0), 0u);
    // Port 1 had nothing assigned: its network starts empty, the internal EPOS2 stays put.
    EXPECT_EQ(device.internal_drive().node().nmt_state(), canopen::NmtState::PreOperational);
}

// 10.15: the manager reaches node n of port 2 on the COB-IDs of its client parameter 0x1280 + n,
// as written, and not at all while they are marked invalid (CAN_SdoRead uses the manager's
// client).
TEST(EposP, TheSdoClientParametersGiveTheManagersCobIds) {
    EposP device;
    auto monitor = device.external_bus().connect("monitor");
    std::vector<std::uint32_t> requests;
    monitor->on_receive([&](const can::Frame& frame) {
        if (frame.dlc == 8) {
            requests.push_back(frame.id);
        }
    });
    canopen::ObjectDictionary& od = device.objects();
    ASSERT_EQ(od.write(0x1285, 1, canopen::encode(std::uint32_t{0x655})), canopen::AbortCode::None);
    ASSERT_EQ(od.write(0x1285, 2, canopen::encode(std::uint32_t{0x5D5})), canopen::AbortCode::None);
    ASSERT_FALSE(device.plc().load(compile_program(R"(
PROGRAM Main
VAR
  Read : CAN_SdoRead;
  Go : BOOL;
END_VAR
Read(Execute := Go, Port := 2, NodeId := 5, Index := 16#1000, SubIndex := 0);
END_PROGRAM
)")));
    ASSERT_FALSE(device.start_program(vm::StartMode::Cold));
    const auto read_device_type = [&] {
        ASSERT_FALSE(device.plc().runtime().write_value<std::uint8_t>("Main.Go", 1));
        device.loop().run_for(2s);
        ASSERT_FALSE(device.plc().runtime().write_value<std::uint8_t>("Main.Go", 0));
        device.loop().run_for(100ms);
    };
    read_device_type();
    // Nobody answers: the request, and at its timeout the abort, on the COB-ID written.
    EXPECT_EQ(requests, (std::vector<std::uint32_t>{0x655, 0x655}));
    EXPECT_EQ(*device.plc().value_of("Main.Read.AbortCode"), "84148224"); // 16#05040000

    ASSERT_EQ(od.write(0x1285, 1, canopen::encode(std::uint32_t{0x8000'0655})),
              canopen::AbortCode::None);
    read_device_type();
    EXPECT_EQ(requests.size(), 2U);                                        // nothing sent
    EXPECT_EQ(*device.plc().value_of("Main.Read.AbortCode"), "101318691"); // 16#060A0023
}

TEST(EposP, BusOffAndErrorPassiveOfPortTwoAreInTheHistory) {
    EposP device;
    // Port 2 is a virtual port here: its faults can be injected.
    auto& port = static_cast<can::VirtualPort&>(device.external_port());
    port.force_error_state(can::ErrorState::Passive);
    port.force_error_state(can::ErrorState::BusOff);
    device.loop().run_for(10ms);
    EXPECT_EQ(history(device, 2), 0x0200'8120u); // port 2, the master, CAN Passive Error
    EXPECT_EQ(history(device, 1), 0x0200'81FDu); // port 2, the master, CAN Bus Off Error
}

// Table 1: 0x81FC, the frame error warning level, as a warning entry (table 4, bit 31) once the
// controller reaches it from error-active, not again on its way back down from passive.
TEST(EposP, TheWarningLevelOfPortTwoIsAWarningInTheHistory) {
    EposP device;
    auto& port = static_cast<can::VirtualPort&>(device.external_port());
    port.force_error_state(can::ErrorState::Warning);
    port.force_error_state(can::ErrorState::Passive);
    port.force_error_state(can::ErrorState::Warning);
    device.loop().run_for(10ms);
    EXPECT_EQ(device.objects().get_as<std::uint8_t>(0x1003, 0), 2u);
    EXPECT_EQ(history(device, 2), 0x8200'81FCu); // warning, port 2, the master, CAN Warning
    EXPECT_EQ(history(device, 1), 0x0200'8120u);
    // A master communication warning in the manufacturer status register (table 3, bit 20).
    EXPECT_NE(device.objects().get_as<std::uint32_t>(0x1002, 0) & (1U << 20), 0u);
}

TEST(EposP, AColdStartOfTheProgramBootsTheNetworks) {
    EposP device;
    ASSERT_FALSE(device.plc().load(compile_program(kDoubler)));
    assign_mandatory(device, kInternalSlaveSubIndex, kInternalPort, 1);
    ASSERT_EQ(write_u16(device, 0x5F51, 0, 1), canopen::AbortCode::None);
    device.loop().run_for(2s);
    EXPECT_TRUE(device.network(kInternalPort).report().network_started);
    EXPECT_EQ(device.internal_drive().node().nmt_state(), canopen::NmtState::Operational);
}

TEST(EposP, TheInternalEpos2sStatuswordArrivesInAxisZeroByItsPdo) {
    EposP device;
    assign_mandatory(device, kInternalSlaveSubIndex, kInternalPort, 1);
    device.boot_networks();
    device.loop().run_for(2s);
    ASSERT_EQ(device.internal_drive().node().nmt_state(), canopen::NmtState::Operational);

    // Shutdown: the drive goes to Ready to Switch On, its TPDO 1 (0x181) sends the statusword,
    // and the controller's internal RPDO 1 (0x1500 / 0x1700) maps it into 0x5280 sub 2.
    ASSERT_EQ(device.internal_drive().objects().write(0x6040, 0, canopen::encode(std::uint16_t{6})),
              canopen::AbortCode::None);
    device.loop().run_for(20ms);
    const auto statusword = device.internal_drive().objects().get_as<std::uint16_t>(0x6041, 0);
    EXPECT_EQ(statusword & 0x006F, 0x0021); // Ready to Switch On
    EXPECT_EQ(device.objects().get_as<std::uint16_t>(0x5280, 2), statusword);
}

TEST(EposP, SyncIsProducedOnBothPortsAsConfigured) {
    EposP device;
    std::size_t internal_syncs = 0;
    std::size_t external_syncs = 0;
    auto internal_monitor = device.internal_bus().connect("monitor");
    auto external_monitor = device.external_bus().connect("monitor");
    internal_monitor->on_receive(
        [&](const can::Frame& frame) { internal_syncs += frame.id == 0x80; });
    external_monitor->on_receive(
        [&](const can::Frame& frame) { external_syncs += frame.id == 0x80; });
    write_u32(device, 0x1006, 0, 1000);        // 1 ms
    write_u32(device, 0x1005, 0, 0x4000'0080); // generate
    device.loop().run_for(100ms);
    EXPECT_NEAR(static_cast<double>(internal_syncs), 100, 1);
    EXPECT_NEAR(static_cast<double>(external_syncs), 100, 1);
}

TEST(EposP, RequestNmtReadsTheSlavesStatesAndSendsCommands) {
    EposP device;
    assign_mandatory(device, kInternalSlaveSubIndex, kInternalPort, 1);
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1F82, kInternalSlaveSubIndex), 0x00u);
    device.boot_networks();
    device.loop().run_for(2s);
    // Table 27: 0x05 operational (heartbeat active).
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1F82, kInternalSlaveSubIndex), 0x05u);

    write_u32(device, 0x1F82, kInternalSlaveSubIndex, 0x04); // stop
    device.loop().run_for(200ms);
    EXPECT_EQ(device.internal_drive().node().nmt_state(), canopen::NmtState::Stopped);
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1F82, kInternalSlaveSubIndex), 0x04u);
    write_u32(device, 0x1F82, kInternalSlaveSubIndex, 0x7F); // enter pre-operational
    device.loop().run_for(200ms);
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1F82, kInternalSlaveSubIndex), 0x7Fu);
    EXPECT_EQ(device.objects().write(0x1F82, kInternalSlaveSubIndex,
                                     canopen::encode(std::uint32_t{0x08})),
              canopen::AbortCode::InvalidValue);
    // A node on port 2 nobody heard of: state unknown.
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1F82, 5), 0x00u);
}

TEST(EposP, OnTheCanBusItIsANodeWithHeartbeatAndAnSdoServer) {
    EposPConfig config;
    config.node_id = 9;
    EposP device(config);
    // A service tool on port 2.
    auto tool = device.external_bus().connect("tool");
    std::vector<can::Frame> heard;
    canopen::SdoClient sdo(device.loop(), *tool);
    tool->on_receive([&](const can::Frame& frame) {
        heard.push_back(frame);
        sdo.on_frame(frame);
    });
    device.loop().run_for(10ms);
    EXPECT_TRUE(heard.empty()); // alone on its bus it sends nothing unasked

    std::optional<std::uint32_t> device_type;
    sdo.upload(9, 0x1000, 0, [&](canopen::AbortCode code, canopen::Bytes value) {
        ASSERT_EQ(code, canopen::AbortCode::None);
        device_type = canopen::decode<std::uint32_t>(value);
    });
    std::optional<canopen::AbortCode> written;
    sdo.download(9, 0x1017, 0, canopen::encode(std::uint16_t{100}),
                 [&](canopen::AbortCode code) { written = code; });
    device.loop().run_for(10ms);
    EXPECT_EQ(device_type, 0x195u);
    EXPECT_EQ(written, canopen::AbortCode::None);

    // 0x1017 = 100 ms: its heartbeat, pre-operational (0x7F) until its network started.
    heard.clear();
    device.loop().run_for(250ms);
    std::vector<std::uint8_t> states;
    for (const can::Frame& frame : heard) {
        if (frame.id == 0x709) {
            states.push_back(frame.payload()[0]);
        }
    }
    EXPECT_EQ(states, (std::vector<std::uint8_t>{0x7F, 0x7F}));
    device.boot_networks(); // nothing assigned: port 2 starts at once
    heard.clear();
    device.loop().run_for(1s);
    ASSERT_FALSE(heard.empty());
    EXPECT_EQ(heard.back().id, 0x709u);
    EXPECT_EQ(heard.back().payload()[0], 0x05);
}

TEST(EposP, TheManufacturerStatusRegisterGathersSlavesErrorRegistersAndMasterWarnings) {
    EposP device;
    const auto status = [&device] {
        return device.objects().get_as<std::uint32_t>(0x1002, 0);
    };
    EXPECT_EQ(status(), 0u);
    // Port 2 is pre-operational from power-up: its EMCY consumer listens.
    auto nodes = device.external_bus().connect("nodes");
    nodes->send(
        can::Frame::data_frame(0x085, {0x10, 0x32, 0x05, 0, 0, 0, 0, 0})); // generic+voltage
    nodes->send(can::Frame::data_frame(0x086, {0x10, 0x81, 0x11, 0, 0, 0, 0, 0})); // generic+comm
    device.loop().run_for(10ms);
    EXPECT_EQ(status(), 0x15u); // bits 0, 2, 4 of table 3
    nodes->send(can::Frame::data_frame(0x085, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0})); // reset
    device.loop().run_for(10ms);
    EXPECT_EQ(status(), 0x11u);

    // An optional slave that does not answer: a warning of the master (bits 16, 20), no bit of
    // the error register.
    write_u32(device, 0x1F81, 9, manager::assignment::kSlave | manager::assignment::kBootSlave);
    device.boot_networks();
    device.loop().run_for(2s);
    ASSERT_EQ(history(device, 1), 0x8209'8182u);
    EXPECT_EQ(status(), 0x0011'0011u);
    // A CAN error of the port sets the error register, copied into bits 8..15.
    static_cast<can::VirtualPort&>(device.external_port())
        .force_error_state(can::ErrorState::Passive);
    device.loop().run_for(10ms);
    EXPECT_EQ(status(), 0x0011'1111u); // 0x1001: the communication and generic bits
    // Clearing the history clears the warnings.
    ASSERT_EQ(device.objects().write(0x1003, 0, canopen::encode(std::uint8_t{0})),
              canopen::AbortCode::None);
    EXPECT_EQ(status() & 0xFFFF'0000u, 0u);
}

} // namespace
} // namespace eposp::device
