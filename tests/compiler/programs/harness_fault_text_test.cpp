// StProgram::fault() describes the fault of the last scans, and is empty when they did not
// fault: tests print it on failure, and stale or made-up text there sends a reader astray.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(HarnessFaultText, IsEmptyWhenTheTaskHasNotFaulted) {
    StProgram run("PROGRAM Main\nVAR x : DINT; END_VAR\nx := x + 1;\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(run.fault(), "");
    ASSERT_TRUE(run.scans(2));
    EXPECT_EQ(run.fault(), "");
}

TEST(HarnessFaultText, NamesTheFaultOfTheLastScanAndClearsWhenTheTaskRunsAgain) {
    StProgram run("PROGRAM Main\nVAR x, y : DINT; END_VAR\n"
                  "x := 10 / y;\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "division by zero in Main at line 3");
    run.set<std::int32_t>("Main.y", 2);
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), 5);
    EXPECT_EQ(run.fault(), "");
}

} // namespace
} // namespace eposp::compiler::test
