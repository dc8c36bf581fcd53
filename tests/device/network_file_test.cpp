// Network files: what they set in the EPOS P's dictionary, and every mistake named with its line.
#include "eposp/device/epos_p.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/manager/concise_dcf.hpp"
#include "eposp_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using testing::HasSubstr;

constexpr const char* kTwoAxes = R"(bit_rate: 500000
boot_time: 800ms
sync_period: 2ms
slaves:
  - node: 1
    port: internal
    axis: 0
    heartbeat: 100ms
    expect:
      vendor_id: 0xFB
  - node: 2
    kind: epos2
    axis: 1
    mandatory: false
    heartbeat: 200ms
    expect:
      product_code: 0x62200000
  - node: 9
    kind: external
    heartbeat: 0ms
)";

TEST(NetworkFile, ReadsSlavesChecksAndAxes) {
    const auto network = parse_network_file(kTwoAxes, "net.yaml");
    ASSERT_TRUE(network.ok()) << network.error();
    EXPECT_EQ(network->bit_rate, 500'000u);
    EXPECT_EQ(network->boot_time, 800ms);
    ASSERT_EQ(network->slaves.size(), 3u);
    EXPECT_EQ(network->slaves[0].port, kInternalPort);
    EXPECT_EQ(network->slaves[0].identity.vendor_id, 0xFBu);
    EXPECT_EQ(network->slaves[1].port, kExternalPort);
    EXPECT_FALSE(network->slaves[1].mandatory);
    EXPECT_EQ(network->slaves[1].axis, std::uint8_t{1});
    EXPECT_EQ(network->slaves[2].kind, NetworkSlave::Kind::External);
    EXPECT_EQ(network->slaves[2].heartbeat_ms, 0u);
}

TEST(NetworkFile, ReadsTheEventsThatReleaseTasks) {
    const auto network = parse_network_file(R"(events:
  - {task: OnSync, on: sync}
  - {task: OnEmcy, on: emcy, node: 4}
  - {task: OnPdo, on: rpdo, port: internal, rpdo: 2}
  - {task: OnKey, on: input, input: "%IX3.7"}
)",
                                            "net.yaml");
    ASSERT_TRUE(network.ok()) << network.error();
    ASSERT_EQ(network->events.size(), 4u);
    EXPECT_EQ(network->events[1].source, EventBinding::Source::Emcy);
    EXPECT_EQ(network->events[1].node, 4);
    EXPECT_EQ(network->events[2].port, kInternalPort);
    EXPECT_EQ(network->events[2].rpdo, 2u);
    EXPECT_EQ(network->events[3].input_byte, 3u);
    EXPECT_EQ(network->events[3].input_bit, 7);
}

TEST(NetworkFile, ReadsTheWiresBetweenTheDevices) {
    const auto network =
        parse_network_file("slaves:\n"
                           "  - {node: 2}\n"
                           "wires:\n"
                           "  - {from: \"%QX0.3\", to: Node 2 Digital Input 6}\n"
                           "  - {from: internal digital output 2, to: \"%IX4.7\"}\n"
                           "  - {from: \"%QW16\", to: node 2 analog input 2}\n"
                           "  - {from: escon2 belt-1 analog output 2, to: \"%IW20\"}\n"
                           "  - {from: \"%QX0.4\", to: ESCON2 belt-1 high-speed digital input 2}\n"
                           "escon2:\n"
                           "  - {name: belt-1, hardware: nano 24/2}\n",
                           "net.yaml");
    ASSERT_TRUE(network) << network.error();
    ASSERT_EQ(network->wires.size(), 5U);
    ASSERT_EQ(network->escon2s.size(), 1U);
    EXPECT_EQ(network->escon2s[0].hardware, drives::escon2::Escon2Hardware::Nano24_2);
    std::vector<std::string> texts;
    for (const SignalWire& wire : network->wires) {
        texts.push_back(to_string(wire.from) + " -> " + to_string(wire.to));
    }
    EXPECT_THAT(texts, testing::ElementsAre("%QX0.3 -> node 2 digital input 6",
                                            "internal digital output 2 -> %IX4.7",
                                            "%QW16 -> node 2 analog input 2",
                                            "escon2 belt-1 analog output 2 -> %IW20",
                                            "%QX0.4 -> escon2 belt-1 high-speed digital input 2"));
}

TEST(RunCommand, AnEventForATaskTheProgramLacksIsAUserError) {
    const std::string program = write_source("main.st", "PROGRAM Main\nEND_PROGRAM\n");
    const std::string network = write_source("net.yaml", "events:\n  - {task: OnSync, on: sync}\n");
    const auto result = eposp("run " + program + " --network " + network + " --for 1s");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output,
                HasSubstr("eposp run: error: event task OnSync: the program has no such task"));
}

TEST(NetworkFile, ASlaveMayTakeNodeOneWhenTheEposPHasAnotherNodeId) {
    const auto network = parse_network_file("node_id: 5\nslaves:\n  - node: 1\n", "net.yaml");
    ASSERT_TRUE(network.ok()) << network.error();
    EXPECT_EQ(network->node_id, 5);
    EXPECT_EQ(network->slaves.at(0).node_id, 1);
}

TEST(NetworkFile, AConciseDcfConfiguresItsSlaveInsteadOfTheAxisSetUp) {
    // A DCF as `eposp dcf` writes them, with a heartbeat of 70 ms and a following error window.
    const std::vector<manager::ConfigurationWrite> writes = {
        {0x1017, 0, canopen::encode(std::uint16_t{70})},
        {0x6065, 0, canopen::encode(std::uint32_t{4321})}};
    const auto bytes = manager::encode_concise_dcf(writes);
    const auto dcf = scratch("node2.cdcf");
    std::ofstream(dcf, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    const auto path = write_source(
        "net.yaml", "slaves:\n  - {node: 2, axis: 1, heartbeat: 0ms, dcf: node2.cdcf}\n");
    const auto network = load_network_file(path);
    ASSERT_TRUE(network.ok()) << network.error();
    ASSERT_TRUE(network->slaves.at(0).concise_dcf);
    EXPECT_EQ(network->slaves.at(0).concise_dcf->size(), 2u);

    EposP device;
    device.add_network(*network);
    device.boot_networks();
    device.loop().run_for(2s);
    const canopen::ObjectDictionary& slave = device.simulated_slaves().at(0)->objects();
    EXPECT_EQ(slave.get_as<std::uint16_t>(0x1017, 0), 70u);
    EXPECT_EQ(slave.get_as<std::uint32_t>(0x6065, 0), 4321u);
    EXPECT_EQ(slave.get_as<std::uint8_t>(0x1A00, 0), 1u); // its TPDO 1 left as it was
}

TEST(NetworkFile, ABrokenOrMissingConciseDcfIsAnErrorAtItsLine) {
    write_source("cut.cdcf", std::string("\x01\x00\x00\x00\x17", 5));
    const auto cut =
        load_network_file(write_source("net.yaml", "slaves:\n  - node: 2\n    dcf: cut.cdcf\n"));
    ASSERT_FALSE(cut.ok());
    EXPECT_THAT(cut.error(), HasSubstr("net.yaml:3:10: error: dcf "));
    EXPECT_THAT(cut.error(), HasSubstr("cut.cdcf: entry 1 of 1 is cut off at byte 4"));
    const auto missing =
        load_network_file(write_source("net2.yaml", "slaves:\n  - {node: 2, dcf: nowhere.cdcf}\n"));
    ASSERT_FALSE(missing.ok());
    EXPECT_THAT(missing.error(), HasSubstr("nowhere.cdcf: cannot read the file"));
}

TEST(NetworkFile, APlantFileGivesASimulatedSlaveItsMachine) {
    write_source("machine.yaml", "switches:\n  home: 6000\n");
    const auto network = load_network_file(
        write_source("net.yaml", "slaves:\n  - {node: 2, plant: machine.yaml}\n"));
    ASSERT_TRUE(network.ok()) << network.error();
    ASSERT_TRUE(network->slaves.at(0).plant);
    EXPECT_EQ(network->slaves.at(0).plant->switches.home, 6000);

    const auto internal = load_network_file(
        write_source("net2.yaml", "slaves:\n  - {node: 1, port: internal, plant: machine.yaml}\n"));
    ASSERT_FALSE(internal.ok());
    EXPECT_THAT(internal.error(), HasSubstr("'plant' is for EPOS2s simulated on the CAN bus"));
    const auto missing = load_network_file(
        write_source("net3.yaml", "slaves:\n  - {node: 2, plant: nowhere.yaml}\n"));
    ASSERT_FALSE(missing.ok());
    EXPECT_THAT(missing.error(), HasSubstr("net3.yaml:2:"));
    EXPECT_THAT(missing.error(), HasSubstr("plant "));
}

TEST(NetworkFile, AConfigurationDateMismatchOnAMandatorySlaveHoldsTheNetworkBack) {
    const auto network =
        parse_network_file("slaves:\n  - node: 2\n    expect: {configuration_date: 14000, "
                           "configuration_time: 3600000}\n",
                           "net.yaml");
    ASSERT_TRUE(network.ok()) << network.error();
    EposP device;
    device.add_network(*network);
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1F26, 2), 14000u);
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1F27, 2), 3600000u);
    device.boot_networks();
    device.loop().run_for(2s);
    EXPECT_FALSE(device.network(kExternalPort).report().network_started);
    // Table 4: port 2, node 2, 0x6386 (the slave's 0x1020 holds no configuration).
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x1003, 1), 0x0202'6386u);
}

TEST(NetworkFile, ApplyWritesTheNetworkListAndTheAxisTable) {
    EposP device;
    device.add_network(*parse_network_file(kTwoAxes, "net.yaml"));
    const canopen::ObjectDictionary& od = device.objects();
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1F89, 0), 800u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1006, 0), 2000u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1005, 0), 0x4000'0080u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1F81, kInternalSlaveSubIndex), 0x0Du);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1F85, kInternalSlaveSubIndex), 0xFBu);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1F81, 2), 0x05u); // optional
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1F86, 2), 0x6220'0000u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1F81, 9), 0x0Du);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1016, 1), 0x0101'0064u); // port 1, node 1, 100 ms
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1016, 2), 0x0202'00C8u); // port 2, node 2, 200 ms
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1016, 3), 0u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x5280, 1), kInternalSlave);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x5281, 1), 2u);
    EXPECT_EQ(device.simulated_slaves().size(), 1u); // node 9 is external
}

struct BadFile {
    const char* name;
    const char* text;
    const char* message; ///< file:line:col: error: ...
};

class NetworkFileMistake : public ::testing::TestWithParam<BadFile> {};

TEST_P(NetworkFileMistake, IsAnErrorAtItsLine) {
    const auto network = parse_network_file(GetParam().text, "net.yaml");
    ASSERT_FALSE(network.ok());
    EXPECT_THAT(network.error(), HasSubstr(GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    All, NetworkFileMistake,
    ::testing::Values(
        BadFile{"UnknownKey", "bit_rate: 1000000\nspeed: 3\n",
                "net.yaml:2:1: error: unknown key 'speed' in 'network'"},
        BadFile{"BitRate", "bit_rate: 300000\n", "net.yaml:1:11: error: bit_rate must be"},
        BadFile{"BitRateAnEpos2Lacks", "bit_rate: 10000\nslaves:\n  - node: 2\n",
                "net.yaml:3:5: error: node 2 is an EPOS2, which cannot run at bit_rate 10000"},
        BadFile{"BootTime", "boot_time: 100ms\n", "net.yaml:1:12: error: boot_time must be"},
        BadFile{"SyncPeriod", "sync_period: 500us\n", "net.yaml:1:14: error: sync_period must be"},
        BadFile{"NotADuration", "boot_time: soon\n",
                "net.yaml:1:12: error: boot_time must be a duration"},
        BadFile{"NodeRange", "slaves:\n  - node: 128\n",
                "net.yaml:2:11: error: node must be 1..127"},
        BadFile{"NoNode", "slaves:\n  - axis: 1\n",
                "net.yaml:2:5: error: a slave needs its 'node'"},
        BadFile{"NodeTwice", "slaves:\n  - node: 3\n  - node: 3\n",
                "net.yaml:3:5: error: node 3 is listed twice"},
        BadFile{"AxisTwice", "slaves:\n  - node: 3\n    axis: 1\n  - node: 4\n    axis: 1\n",
                "net.yaml:4:5: error: axis 1 is served twice"},
        BadFile{"AxisRange", "slaves:\n  - node: 3\n    axis: 32\n",
                "net.yaml:3:11: error: axis must be 0..31"},
        BadFile{"InternalNode", "slaves:\n  - node: 2\n    port: internal\n",
                "net.yaml:2:5: error: the internal slave is the EPOS2 with node 1"},
        BadFile{"Kind", "slaves:\n  - node: 2\n    kind: escon\n",
                "net.yaml:3:11: error: kind must be"},
        BadFile{"Syntax", "slaves: [\n", "net.yaml:"},
        BadFile{"NotAList", "slaves: 3\n", "net.yaml:1:9: error: 'slaves' must be a list"},
        BadFile{"OwnNodeId", "slaves:\n  - node: 1\n",
                "net.yaml:2:5: error: node 1 is the EPOS P's own node-ID on the CAN bus"},
        BadFile{"OwnNodeIdSetLater", "slaves:\n  - node: 7\nnode_id: 7\n",
                "net.yaml:2:5: error: node 7 is the EPOS P's own node-ID"},
        BadFile{"NodeIdRange", "node_id: 0\n", "net.yaml:1:10: error: node_id must be 1..127"},
        BadFile{"EventSource", "events:\n  - {task: T, on: timer}\n",
                "net.yaml:2:19: error: on must be 'sync', 'emcy', 'rpdo' or 'input'"},
        BadFile{"EventWithoutTask", "events:\n  - {on: sync}\n",
                "net.yaml:2:5: error: an event needs its 'task'"},
        BadFile{"EventRpdo", "events:\n  - {task: T, on: rpdo, port: internal, rpdo: 5}\n",
                "net.yaml:2:47: error: an rpdo event needs 'rpdo'"},
        BadFile{"EventInput", "events:\n  - {task: T, on: input, input: \"%IX224.0\"}\n",
                "net.yaml:2:33: error: input must be a process input bit"},
        BadFile{"WireFromAnInput", "wires:\n  - {from: \"%IX0.0\", to: internal digital input 1}\n",
                "net.yaml:2:5: error: '%IX0.0' is an input: a wire runs from an output"},
        BadFile{"WireToAnOutput", "wires:\n  - {from: \"%QX0.0\", to: internal digital output 1}\n",
                "net.yaml:2:5: error: 'internal digital output 1' is an output: a wire runs to an "
                "input"},
        BadFile{"WireOfTwoKinds", "wires:\n  - {from: \"%QW16\", to: internal digital input 1}\n",
                "net.yaml:2:5: error: '%QW16' is analog but 'internal digital input 1' is digital"},
        BadFile{"WireToAMissingPin",
                "wires:\n  - {from: \"%QX0.0\", to: internal digital input 7}\n",
                "net.yaml:2:26: error: to: an EPOS2 24/5 has digital inputs 1..6"},
        BadFile{"WireOutsideTheImage", "wires:\n  - {from: \"%QX224.0\", to: \"%IX0.0\"}\n",
                "net.yaml:2:12: error: from: a wire's end is"},
        BadFile{"WireWithoutTo", "wires:\n  - {from: \"%QX0.0\"}\n",
                "net.yaml:2:5: error: a wire needs its 'from' (an output) and its 'to'"},
        BadFile{"WireToAnUnsimulatedNode",
                "slaves:\n  - {node: 3, kind: external}\nwires:\n  - {from: \"%QX0.0\", to: node 3 "
                "digital input 1}\n",
                "net.yaml:4:5: error: 'node 3 digital input 1': node 3 is no EPOS2 simulated"},
        BadFile{"InputWiredTwice",
                "wires:\n  - {from: \"%QX0.0\", to: \"%IX1.0\"}\n  - {from: \"%QX0.1\", to: "
                "\"%ix1.0\"}\n",
                "net.yaml:3:5: error: '%IX1.0' is wired twice"},
        BadFile{"WireToAnUnknownEscon2",
                "wires:\n  - {from: \"%QX0.0\", to: escon2 belt digital input 1}\n",
                "net.yaml:2:5: error: 'escon2 belt digital input 1': no ESCON2 is named 'belt'"},
        BadFile{"Escon2WithoutName", "escon2:\n  - {hardware: Nano 24/2}\n",
                "net.yaml:2:5: error: an ESCON2 needs its 'name'"},
        BadFile{"Escon2Hardware", "escon2:\n  - {name: a, hardware: Giga 99/9}\n",
                "net.yaml:2:25: error: hardware must be 'Module 60/30'"},
        BadFile{"Escon2NameTwice", "escon2:\n  - {name: a}\n  - {name: a}\n",
                "net.yaml:3:5: error: an ESCON2 named 'a' is listed twice"},
        BadFile{"Escon2UnknownObject",
                "escon2:\n  - name: a\n    parameters:\n      - {index: 0x5555, value: 1}\n",
                "net.yaml:4:9: error: 0x5555 sub 0: the ESCON2 has no such object"},
        BadFile{"Escon2RefusedValue",
                "escon2:\n  - name: a\n    parameters:\n      - {index: 0x3142, sub: 1, value: "
                "200}\n",
                "net.yaml:4:9: error: 0x3142 sub 1: the ESCON2 refuses 200:"},
        BadFile{"Escon2ValueOutsideItsType",
                "escon2:\n  - name: a\n    parameters:\n      - {index: 0x3142, sub: 1, value: "
                "300}\n",
                "net.yaml:4:9: error: 0x3142 sub 1: 300 does not fit its type UNSIGNED8"},
        BadFile{
            "Escon2PinOutOfRange",
            "escon2:\n  - {name: a}\nwires:\n  - {from: escon2 a high-speed digital output 2, "
            "to: \"%IX0.0\"}\n",
            "net.yaml:4:12: error: from: an ESCON2 has one high-speed digital output, number 1"}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(RunCommand, WithANetworkPrintsTheBootReport) {
    const std::string program =
        write_source("main.st", "PROGRAM Main\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n");
    const std::string network = write_source("net.yaml", kTwoAxes);
    const auto result = eposp("run " + program + " --network " + network + " --for 3s");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("boot-up of port 1 (internal): network started"));
    EXPECT_THAT(result.output, HasSubstr("node 1: booted at"));
    EXPECT_THAT(result.output, HasSubstr("node 2: booted at"));
    // Node 9 is not there: no answer, and as a mandatory slave it holds port 2 back.
    EXPECT_THAT(result.output, HasSubstr("boot-up of port 2 (CAN): held back"));
    EXPECT_THAT(result.output, HasSubstr("node 9: failed at"));
    EXPECT_THAT(result.output, HasSubstr("0x8182 CAN No Answer Error"));
}

TEST(RunCommand, ABadNetworkFileIsAUserErrorWithItsLine) {
    const std::string program = write_source("main.st", "PROGRAM Main\nEND_PROGRAM\n");
    const std::string network = write_source("net.yaml", "slaves:\n  - node: 0\n");
    const auto result = eposp("run " + program + " --network " + network);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("net.yaml:2:11: error: node must be 1..127"));
}

TEST(RunCommand, ADirectoryAsTheNetworkFileIsAUserError) {
    const std::string program = write_source("main.st", "PROGRAM Main\nEND_PROGRAM\n");
    const auto directory = scratch("network-dir");
    std::filesystem::create_directories(directory);
    const auto result = eposp("run " + program + " --network " + directory.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(directory.string() + " is a directory"));
}

} // namespace
} // namespace eposp::device
