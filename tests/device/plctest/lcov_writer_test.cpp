// The lcov tracefile of `eposp test --coverage`: a golden file for a report of two source files
// (a library POU without a source left out), and the file read back by lcov itself where it is
// installed.

#include "eposp/plctest/lcov_writer.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

namespace eposp::plctest {
namespace {

vm::CoverageReport sample_report() {
    vm::CoverageReport report;
    vm::PouCoverage& main = report.pous["Main"];
    main.calls = 5;
    main.lines = {{7, 5}, {8, 5}, {9, 3}, {12, 0}};
    main.branches[{8, 0}] = {0, 5};
    main.branches[{8, 1}] = {2, 3};
    main.branches[{12, 0}] = {0, 0, 0, 0};
    vm::PouCoverage& twice = report.pous["Twice"];
    twice.calls = 3;
    twice.lines = {{3, 3}};
    vm::PouCoverage& unused = report.pous["Unused"];
    unused.lines = {{20, 0}};
    report.pous["MC_Power"].lines = {{1, 4}}; // a library block: no source given
    return report;
}

const std::map<std::string, std::string> kSources = {
    {"Main", "/src/main.st"}, {"Twice", "/src/main.st"}, {"Unused", "/src/util.st"}};

TEST(LcovWriter, WritesOneRecordPerSourceFile) {
    EXPECT_EQ(lcov_tracefile(sample_report(), kSources, "unit tests"), R"(TN:unit_tests
SF:/src/main.st
FN:3,Twice
FN:7,Main
FNDA:3,Twice
FNDA:5,Main
FNF:2
FNH:2
BRDA:8,0,0,0
BRDA:8,0,1,5
BRDA:8,1,0,2
BRDA:8,1,1,3
BRDA:12,0,0,-
BRDA:12,0,1,-
BRDA:12,0,2,-
BRDA:12,0,3,-
BRF:8
BRH:3
DA:3,3
DA:7,5
DA:8,5
DA:9,3
DA:12,0
LF:5
LH:4
end_of_record
TN:unit_tests
SF:/src/util.st
FN:20,Unused
FNDA:0,Unused
FNF:1
FNH:0
BRF:0
BRH:0
DA:20,0
LF:1
LH:0
end_of_record
)");
}

/// lcov's own reading of `tracefile`: the output of `lcov --summary`, or nullopt without lcov.
std::optional<std::string> lcov_summary(const std::string& tracefile) {
    if (std::system("command -v lcov >/dev/null 2>&1") != 0) {
        return std::nullopt;
    }
    const auto dir =
        std::filesystem::temp_directory_path() / ("eposp_lcov_writer_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "coverage.info") << tracefile;
    const std::string command = "lcov --rc lcov_branch_coverage=1 --summary '" +
                                (dir / "coverage.info").string() + "' >'" +
                                (dir / "summary.txt").string() + "' 2>&1";
    const int status = std::system(command.c_str());
    std::stringstream text;
    text << std::ifstream(dir / "summary.txt").rdbuf();
    std::filesystem::remove_all(dir);
    EXPECT_EQ(status, 0) << text.str();
    return text.str();
}

TEST(LcovWriter, LcovReadsTheTracefile) {
    const auto summary = lcov_summary(lcov_tracefile(sample_report(), kSources, "unit"));
    if (!summary) {
        GTEST_SKIP() << "lcov is not installed";
    }
    EXPECT_NE(summary->find("lines......: 66.7% (4 of 6 lines)"), std::string::npos) << *summary;
    EXPECT_NE(summary->find("functions..: 66.7% (2 of 3 functions)"), std::string::npos)
        << *summary;
    EXPECT_NE(summary->find("branches...: 37.5% (3 of 8 branches)"), std::string::npos) << *summary;
}

} // namespace
} // namespace eposp::plctest
