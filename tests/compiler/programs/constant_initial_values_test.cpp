// An initial value is a constant expression of the variable's type (IEC 61131-3 ed. 3, 6.5.1.3):
// named CONSTANTs of every type and durations scaled by integers fold when compiling, to the
// value the same expression has at run time. Typing accepted them and code generation refused
// them (E0313: `eposp check` passed, `eposp build` failed).
#include "codegen_harness.hpp"

#include <cstdint>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(ConstantInitialValues, FoldToTheValueTheExpressionHasAtRunTime) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kPeriod : TIME := T#1ms * 4;
    kStart : TIME := T#1s;
    kRatio : REAL := 1.5;
    kQuarter : INT := 7 / 2;
    kOn : BOOL := TRUE;
    kName : STRING := 'ab';
END_VAR
VAR
    period : TIME := kPeriod; period_now : TIME;
    half : TIME := kStart / 2 - T#100ms; half_now : TIME;
    back : TIME := -kPeriod / -1; back_now : TIME;
    start : DT := DT#2020-01-01-00:00:00 + T#1h; start_now : DT;
    ratio : LREAL := kRatio * 2.0;
    quarter : REAL := kQuarter;
    lit : BOOL := kOn;
    name : STRING := kName;
END_VAR
period_now := T#1ms * 4;
half_now := kStart / 2 - T#100ms;
back_now := -kPeriod / -1;
start_now := DT#2020-01-01-00:00:00 + T#1h;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    const auto period = run.get<std::int64_t>("Main.period");
    const auto half = run.get<std::int64_t>("Main.half");
    const auto back = run.get<std::int64_t>("Main.back");
    const auto start = run.get<std::int64_t>("Main.start");
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(period, 4'000'000);
    EXPECT_EQ(period, run.get<std::int64_t>("Main.period_now"));
    EXPECT_EQ(half, 400'000'000);
    EXPECT_EQ(half, run.get<std::int64_t>("Main.half_now"));
    EXPECT_EQ(back, 4'000'000);
    EXPECT_EQ(back, run.get<std::int64_t>("Main.back_now"));
    EXPECT_EQ(start, run.get<std::int64_t>("Main.start_now"));
    EXPECT_EQ(run.get<double>("Main.ratio"), 3.0);
    EXPECT_EQ(run.get<float>("Main.quarter"), 3.0F); // the INT constant's value, not 3.5
    EXPECT_TRUE(run.get<bool>("Main.lit"));
    EXPECT_EQ(run.get_string("Main.name"), "ab");
}

} // namespace
} // namespace eposp::compiler::test
