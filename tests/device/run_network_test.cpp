// `eposp run --network` as a user runs it: the two-axis example with its boot report and axis
// trace, byte-identical traces and bus logs from two runs, and outputs that must not overwrite
// inputs.
#include "eposp_command.hpp"

#include <gtest/gtest.h>
#include <sstream>
#include <vector>

namespace eposp::device {
namespace {

const std::string kExample = std::string(EPOSP_SOURCE_DIR) + "/examples/two-axis/";
const std::string kRunExample =
    "run " + kExample + "two-axis.st --network " + kExample + "network.yaml --for 5s";

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

TEST(RunNetwork, TheTwoAxisExampleBootsBothPortsAndTracesBothAxesToTheirTargets) {
    const auto trace = scratch("axes.csv");
    const auto result = eposp(kRunExample + " --watch Cell.both_done --trace " + trace.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("boot-up of port 1 (internal): network started\n"
                                 "  node 1: booted at"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("boot-up of port 2 (CAN): network started\n  node 2: booted at"),
              std::string::npos);
    EXPECT_NE(result.output.find("Cell.both_done = TRUE"), std::string::npos);

    const auto rows = lines_of(read_file(trace));
    ASSERT_EQ(rows.size(), 1 + 2 * 5001u); // the header, both axes at 0, 1, ... 5000 ms
    EXPECT_EQ(rows[0] + "\n", "time_s,axis,statusword,mode,target_position,position_demand,"
                              "actual_position,velocity_demand,actual_velocity,current_mA,"
                              "plcopen_state\n");
    // At the end both are at their targets, Operation Enabled with Target Reached and Remote
    // (0x0737 = 1847), in profile position mode (1), standing still.
    EXPECT_TRUE(rows[rows.size() - 2].starts_with("5.000000000,0,1847,1,20000,20000,20000,0,0,"))
        << rows[rows.size() - 2];
    EXPECT_TRUE(rows.back().starts_with("5.000000000,1,1847,1,-12000,-12000,-12000,0,0,"))
        << rows.back();
}

TEST(RunNetwork, TwoRunsOfTheSameNetworkAndProgramGiveByteIdenticalTracesAndBusLogs) {
    std::vector<std::string> traces;
    std::vector<std::string> logs;
    std::vector<std::string> pcaps;
    for (const std::string run : {"first", "second"}) {
        const auto trace = scratch(run + ".csv");
        const auto log = scratch(run + ".log");
        const auto pcap = scratch(run + ".pcap");
        const auto result = eposp(kRunExample + " --trace " + trace.string() + " --can-log " +
                                  log.string() + " --pcap " + pcap.string());
        ASSERT_EQ(result.exit_code, 0) << result.output;
        traces.push_back(read_file(trace));
        logs.push_back(read_file(log));
        pcaps.push_back(read_file(pcap));
    }
    EXPECT_GT(logs[0].size(), 100'000u); // five seconds of SYNCs, PDOs and heartbeats
    EXPECT_EQ(traces[0], traces[1]);
    EXPECT_EQ(logs[0], logs[1]);
    EXPECT_EQ(pcaps[0], pcaps[1]);
    // The log holds both buses under their names.
    EXPECT_NE(logs[0].find(") internal 181#"), std::string::npos);
    EXPECT_NE(logs[0].find(") external 182#"), std::string::npos);
}

TEST(RunNetwork, AnOutputThatNamesAnInputIsRefusedAndTheInputKept) {
    const std::string network = read_file(kExample + "network.yaml");
    const auto copy = write_source("net.yaml", network);
    const auto result =
        eposp("run " + kExample + "two-axis.st --network " + copy + " --for 1s --can-log " + copy);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("error: --can-log " + copy + " would overwrite the input"),
              std::string::npos)
        << result.output;
    EXPECT_EQ(read_file(copy), network);
}

TEST(RunNetwork, ADirectoryWhereTheTraceBelongsIsAClearError) {
    const auto directory = scratch("a-directory");
    std::filesystem::create_directories(directory);
    const auto result = eposp(kRunExample + " --trace " + directory.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.output.find("eposp run: error: --trace"), std::string::npos) << result.output;
}

// The main part of `./eposp.sh demo`.
TEST(RunNetwork, TheTwoAxisDemoRunsToTheEnd) {
    const auto dir = scratch("demo");
    const auto result = test::run_command("EPOSP_DEMO_DIR=" + dir.string() + " " + kExample +
                                          "run.sh " + kEposp + " 2>&1");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("Cell.both_done = TRUE"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("1.5 s   axis 0   20000 qc      0 rpm   axis 1  -12000 qc"),
              std::string::npos)
        << result.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "two-axis.pcap"));
}

} // namespace
} // namespace eposp::device
