// Time and date arithmetic (IEC 61131-3 ed. 3, table 30) laid out at the result type the typing
// stage gives each operation (types/operator_typing.cpp, time_arithmetic): a time of day moved
// by a duration wraps around midnight at either width, the long forms subtract and scale like
// the short ones, and the named functions compute what the operators do.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;
constexpr std::int64_t kDay = 86'400 * kSecond;

TEST(TimeArithmetic, EveryOperatorAtTheTypingStagesResultType) {
    StProgram run(R"(
PROGRAM Main
VAR t : TIME := T#1s; lt : LTIME := LTIME#2us; d : DATE := D#2024-01-31;
    tod1 : TOD := TOD#23:59:59; ltod1 : LTOD := LTOD#00:00:01; dt1 : DT := DT#2024-01-31-12:00:00;
    ldt1 : LDT := LDT#2024-01-31-12:00:00; n : INT := 3; r : LREAL := 2.5;
    sum, wrapped, back, late, days, since, scaled : TIME; lsum, lsince, lscaled : LTIME;
    lwrapped : LTOD; moved : DT; lmoved : LDT; joined : DT; END_VAR
sum := t + t - lt;
lsum := lt + t;
wrapped := TOD_TO_TIME(tod1 + T#2s);
back := TOD_TO_TIME(TOD#00:00:00 - t);
lwrapped := ltod1 - LTIME#2s;
late := tod1 - TOD#12:00:00;
days := d - D#2024-01-01;
moved := dt1 + lt;
lmoved := ldt1 - t;
since := dt1 - DT#2024-01-31-11:00:00;
lsince := ldt1 - LDT#2024-01-31-11:59:59;
scaled := t * n;
lscaled := lt / r;
joined := CONCAT_DATE_TOD(d, ADD_TOD_TIME(tod1, T#1s));
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    const auto get = [&](const char* name) {
        return run.get<std::int64_t>(name);
    };
    EXPECT_EQ(get("Main.sum"), 2 * kSecond - 2'000);
    EXPECT_EQ(get("Main.lsum"), kSecond + 2'000);
    EXPECT_EQ(get("Main.wrapped"), kSecond);
    EXPECT_EQ(get("Main.back"), kDay - kSecond);
    EXPECT_EQ(get("Main.lwrapped"), kDay - kSecond);
    EXPECT_EQ(get("Main.late"), (11 * 3600 + 59 * 60 + 59) * kSecond);
    EXPECT_EQ(get("Main.days"), 30 * kDay);
    EXPECT_EQ(get("Main.moved") - get("Main.dt1"), 2'000);
    EXPECT_EQ(get("Main.ldt1") - get("Main.lmoved"), kSecond);
    EXPECT_EQ(get("Main.since"), 3600 * kSecond);
    EXPECT_EQ(get("Main.lsince"), kSecond);
    EXPECT_EQ(get("Main.scaled"), 3 * kSecond);
    EXPECT_EQ(get("Main.lscaled"), 800);
    EXPECT_EQ(get("Main.joined"), get("Main.d")) << "23:59:59 + 1 s wraps to midnight";
}

} // namespace
} // namespace eposp::compiler::test
