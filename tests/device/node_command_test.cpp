// `eposp node` driven as a user drives it: a node from the shipped sample EDS, browsed over
// socketcand by examples/canopen-node/sdo_browse.py (python-can), and its error paths.
#include "eposp_command.hpp"
#include "sample_device.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using test::run_command;
using testing::HasSubstr;

const std::string kExampleDir = std::string(EPOSP_SOURCE_DIR) + "/examples/canopen-node";
const std::string kSampleEds = kExampleDir + "/sample-device.eds";

TEST(NodeCommand, ShippedSampleEdsIsTheExportOfTheSampleDevice) {
    const std::string exported = sample_device_eds();
    const auto fresh = scratch("sample-device.eds");
    std::ofstream(fresh, std::ios::binary) << exported;
    EXPECT_EQ(read_file(kSampleEds), exported)
        << "the export changed: cp " << fresh.string() << " " << kSampleEds;
}

TEST(NodeCommand, VirtualRunBootsTheNodeAndPrintsItsSummary) {
    const auto log = scratch("bus.log");
    const auto result =
        eposp("node --virtual --for 1s --eds " + kSampleEds + " --node-id 5 --log " + log.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("node 5 (eposp sample I/O module) on bus can0\n"));
    EXPECT_THAT(result.output, HasSubstr("node 5: Pre-operational"));
    EXPECT_THAT(result.output, HasSubstr("bus can0 at 1000 kbit/s: 1.000 s, 1 frames"));
    // CiA 301 7.2.8.3.2.3: the boot-up message, and nothing else from a silent node.
    EXPECT_THAT(read_file(log), testing::EndsWith(" can0 705#00\n"));
}

/// Runs `eposp node` on the sample EDS (node 5, socketcand on a free port) and, against it,
/// sdo_browse.py reading `browsed_eds`; the result is the script's.
test::CommandResult browse_sample_node(const std::filesystem::path& out,
                                       const std::string& browsed_eds) {
    return run_command(
        "sh -c '" +
        start_in_background(out, "node --eds " + kSampleEds +
                                     " --node-id 5 --socketcand 127.0.0.1:0 --for 60s") +
        "/usr/bin/python3 " + kExampleDir + "/sdo_browse.py " + browsed_eds +
        " 5 ${address%:*} ${address##*:} 2>&1; code=$?; kill -INT $pid; wait $pid; exit $code'");
}

// The acceptance run: an outside tool browses the whole dictionary of a node built
// from an exported EDS, over the socketcand bridge.
TEST(NodeCommand, PythonSdoBrowseReadsEveryEntryOfTheSampleDevice) {
    const auto out = scratch("node.out");
    const auto result = browse_sample_node(out, kSampleEds);
    if (result.exit_code == 77) {
        GTEST_SKIP() << "python-can is not installed (Debian: python3-can)";
    }
    ASSERT_EQ(result.exit_code, 0) << result.output << read_file(out);
    const auto entries = sample_device_entries();
    EXPECT_THAT(result.output,
                HasSubstr(fmt::format("browsed node 5: {} entries, {} read, {} "
                                      "matched",
                                      entries.all, entries.readable, entries.readable)));
    EXPECT_THAT(result.output, HasSubstr(", 0 mismatches"));
    EXPECT_THAT(read_file(out), HasSubstr("interrupted"));
}

TEST(NodeCommand, PythonSdoBrowseReportsAValueThatDiffersFromTheEds) {
    std::string eds = read_file(kSampleEds);
    const std::string unsigned16 = "ParameterName=Unsigned16\nObjectType=0x7\nDataType=0x0006\n"
                                   "AccessType=rw\nDefaultValue=0xEA60";
    ASSERT_NE(eds.find(unsigned16), std::string::npos);
    eds.replace(eds.find(unsigned16) + unsigned16.size() - 4, 4, "EA61");
    const auto changed = scratch("changed.eds");
    std::ofstream(changed, std::ios::binary) << eds;

    const auto result = browse_sample_node(scratch("node.out"), changed.string());
    if (result.exit_code == 77) {
        GTEST_SKIP() << "python-can is not installed (Debian: python3-can)";
    }
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_THAT(result.output,
                HasSubstr("MISMATCH 0x2000 sub 7 (Unsigned16): read 60ea, EDS default 61ea"));
    EXPECT_THAT(result.output, HasSubstr(", 1 mismatches"));
}

/// A socketcand client of node 5: with `save`, it writes the heartbeat time, saves (0x1010 sub 1
/// "save"), configures 250 kbit/s by LSS and stores the LSS configuration, printing each answer;
/// then it reads the heartbeat time back.
std::filesystem::path storing_client() {
    const auto client = scratch("storing_client.py");
    std::ofstream(client) << "import sys\n"
                             "sys.path.insert(0, sys.argv[1])\n"
                             "import can, sdo_browse\n"
                             "bus = can.Bus(interface='socketcand', channel='can0', "
                             "host=sys.argv[2], port=int(sys.argv[3]))\n"
                             "sdo = sdo_browse.SdoClient(bus, 5)\n"
                             "def lss(cs, *data):\n"
                             "    bus.send(can.Message(arbitration_id=0x7E5, is_extended_id=False,"
                             " data=bytes([cs, *data]) + bytes(7 - len(data))))\n"
                             "    while cs != 0x04:\n"
                             "        reply = bus.recv(2.0)\n"
                             "        if reply is None:\n"
                             "            return 'no answer'\n"
                             "        if reply.arbitration_id == 0x7E4 and reply.data[0] == cs:\n"
                             "            return reply.data[1]\n"
                             "if sys.argv[4] == 'save':\n"
                             "    sdo.download(0x1017, 0, (250).to_bytes(2, 'little'))\n"
                             "    sdo.download(0x1010, 1, b'save')\n"
                             "    lss(0x04, 0x01)\n"
                             "    print('lss bit timing', lss(0x13, 0, 3))\n"
                             "    print('lss store', lss(0x17))\n"
                             "    lss(0x04, 0x00)\n"
                             "print('heartbeat time', int.from_bytes(sdo.upload(0x1017, 0), "
                             "'little'))\n"
                             "bus.shutdown()\n";
    return client;
}

/// Runs `eposp node` on the sample EDS with `storage` options and storing_client() `action`
/// against it.
test::CommandResult run_storing_client(const std::string& storage, const std::string& action) {
    return run_command("sh -c '" +
                       start_in_background(scratch(action + ".out"),
                                           "node --eds " + kSampleEds +
                                               " --node-id 5 --socketcand 127.0.0.1:0 --for 60s " +
                                               storage) +
                       "/usr/bin/python3 " + storing_client().string() + " " + kExampleDir +
                       " ${address%:*} ${address##*:} " + action +
                       " 2>&1; code=$?; kill -INT $pid; wait $pid; exit $code'");
}

struct StorageCase {
    std::string name;
    std::string options;        ///< {dir}: the test's own directory
    std::string parameter_file; ///< where the parameters must be, under {dir}
    friend void PrintTo(const StorageCase& c, std::ostream* os) { *os << c.name; }
};

class NodeStorage : public testing::TestWithParam<StorageCase> {};

// CiA 301 7.5.2.13 and CiA 305 store configuration: "save" to 0x1010 sub 1 stores the
// parameters, LSS stores the configuration beside them, and the next run of the node starts
// with them: by default in the node's state directory ($XDG_STATE_HOME/eposp/node-5, which the
// tests point at their own directory), or where --state-dir or --parameter-file say.
TEST_P(NodeStorage, SavedParametersAndLssConfigurationComeBackAtTheNextRun) {
    const std::string dir = test::test_directory().string();
    const auto expand = [&dir](std::string text) {
        for (auto at = text.find("{dir}"); at != std::string::npos; at = text.find("{dir}")) {
            text.replace(at, 5, dir);
        }
        return text;
    };
    const std::string options = expand(GetParam().options);
    const auto saved = run_storing_client(options, "save");
    if (saved.exit_code != 0 && saved.output.find("No module named 'can'") != std::string::npos) {
        GTEST_SKIP() << "python-can is not installed (Debian: python3-can)";
    }
    ASSERT_EQ(saved.exit_code, 0) << saved.output;
    EXPECT_THAT(saved.output, HasSubstr("lss bit timing 0\n")); // BaudRate_250=1
    EXPECT_THAT(saved.output, HasSubstr("lss store 0\n"));
    EXPECT_THAT(saved.output, HasSubstr("heartbeat time 250"));
    const std::filesystem::path parameters = expand(GetParam().parameter_file);
    EXPECT_TRUE(std::filesystem::is_regular_file(parameters)) << parameters;
    EXPECT_TRUE(std::filesystem::is_regular_file(parameters.string() + ".lss")) << parameters;
    const auto read = run_storing_client(options, "read");
    ASSERT_EQ(read.exit_code, 0) << read.output;
    EXPECT_THAT(read.output, HasSubstr("heartbeat time 250"));
    // The stored LSS bit rate is the node's at power-up; the simulated bus keeps its own.
    EXPECT_THAT(read_file(scratch("read.out")),
                HasSubstr("node 5: bit rate 250000 bit/s by LSS (the simulated bus runs at "
                          "1000000 bit/s)"));
}

INSTANTIATE_TEST_SUITE_P(
    Places, NodeStorage,
    testing::Values(
        StorageCase{"StateDirectoryByDefault", "", "{dir}/xdg-state/eposp/node-5/parameters.bin"},
        StorageCase{"StateDirOption", "--state-dir {dir}/state", "{dir}/state/parameters.bin"},
        StorageCase{"ParameterFileOption", "--parameter-file {dir}/node.par", "{dir}/node.par"}),
    [](const testing::TestParamInfo<StorageCase>& storage) { return storage.param.name; });

struct UserError {
    std::string arguments;
    std::string message;
};

class NodeCommandUserError : public testing::TestWithParam<UserError> {};

TEST_P(NodeCommandUserError, ExitsWithOneAndSaysWhy) {
    const auto result = eposp("node --virtual --for 1s " + GetParam().arguments);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, NodeCommandUserError,
    testing::Values(
        UserError{"--eds /nonexistent/dev.eds --node-id 5",
                  "eposp node: error: cannot read /nonexistent/dev.eds"},
        UserError{"--eds " + std::string(EPOSP_SOURCE_DIR) +
                      "/examples/bus-demo/canopen-network.log --node-id 5",
                  "eposp node: " + std::string(EPOSP_SOURCE_DIR) +
                      "/examples/bus-demo/canopen-network.log:1: error: "},
        UserError{"--eds /dev/null --node-id 5",
                  "eposp node: error: /dev/null: lists no object ([MandatoryObjects]"},
        UserError{"--eds " + kSampleEds + " --node-id 0", "--node-id: Value 0 not in range"},
        UserError{"--eds " + kSampleEds + " --node-id 128", "--node-id: Value 128 not in range"},
        UserError{"--node-id 5", "--eds is required"},
        UserError{"--eds " + kSampleEds + " --node-id 5 --state-dir /dev/null",
                  "state directory /dev/null"},
        UserError{"--eds " + kSampleEds + " --node-id 5 --bitrate 300000",
                  "--bitrate 300000 is not a CANopen bit rate"}));

TEST(NodeCommand, AddressInUseIsAUserError) {
    const auto out = scratch("bus.out");
    const auto result = run_command(
        "sh -c '" + start_in_background(out, "bus --socketcand 127.0.0.1:0") + kEposp +
        " node --eds " + kSampleEds +
        " --node-id 5 --socketcand $address --for 1s 2>&1; code=$?; kill -INT $pid; wait "
        "$pid; exit $code'");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp node: error: "));
    EXPECT_THAT(result.output, HasSubstr("127.0.0.1:"));
}

} // namespace
} // namespace eposp::device
