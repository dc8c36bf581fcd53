// The seven benchmark programs of ../shared/bench, compiled and run for exactly 1000 scans on a
// clock advancing 1 ms per scan, give the results of the table in their README.
#include "codegen_harness.hpp"

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace eposp::compiler::test {
namespace {

struct Expected {
    std::string program;
    std::int32_t result;
    double r;
};

class BenchResult : public testing::TestWithParam<Expected> {};

TEST_P(BenchResult, ThousandScansGiveTheTableValues) {
    const Expected& expected = GetParam();
    std::ifstream file(std::string(EPOSP_SOURCE_DIR) + "/tests/compiler/inputs/" +
                       expected.program + ".st");
    std::stringstream text;
    text << file.rdbuf();
    StProgram run(text.str());
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1000)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Config0.cycles"), 1000);
    EXPECT_EQ(run.get<std::int32_t>("Config0.result"), expected.result);
    EXPECT_NEAR(run.get<double>("Config0.r"), expected.r, 5e-7);
}

INSTANTIATE_TEST_SUITE_P(Shared, BenchResult,
                         testing::Values(Expected{"bubble_sort", 83864152, 83864.152},
                                         Expected{"sieve", 1027, 1027142.0},
                                         Expected{"crc32", 1099718708, 514947.0},
                                         Expected{"pid_plant", 736487, 736.486794},
                                         Expected{"conveyor_fsm", 22607, 356707.0},
                                         Expected{"fb_channels", 14696, 0.0},
                                         Expected{"strings", 673161, 673.161}),
                         [](const auto& program) { return program.param.program; });

} // namespace
} // namespace eposp::compiler::test
