// Every path from a real number to a duration rounds ties to even (IEC 60559), as REAL_TO_TIME
// does (to its unit, the millisecond): MUL_TIME and DIV_TIME by a REAL or LREAL, `*` and `/` of
// a TIME by a real, and the fraction of a TIME or TOD literal, to the nanosecond. They rounded
// ties away from zero.
#include "codegen_harness.hpp"

#include <cstdint>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(RealToDurationRounding, TimeScaledByARealRoundsTiesToEven) {
    StProgram run(R"(PROGRAM Main
VAR three : TIME := T#3ns; half : LREAL := 0.5; r : REAL := 2.0;
    a, b, c, d, e, f, g, h, i : TIME; j : LTIME; END_VAR
a := MUL_TIME(three, half); b := MUL_TIME(T#5ns, 0.5); c := MUL_TIME(T#-3ns, half);
d := DIV_TIME(three, r); e := DIV_TIME(T#5ns, LREAL#2.0);
f := three * half; g := T#7ns / r; h := MUL_TIME(T#7ns, 0.5);
i := REAL_TO_TIME(2.5); j := LREAL_TO_LTIME(half * 5.0);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int64_t>("Main.a"), 2);         // 1.5 ns
    EXPECT_EQ(run.get<std::int64_t>("Main.b"), 2);         // 2.5 ns
    EXPECT_EQ(run.get<std::int64_t>("Main.c"), -2);        // -1.5 ns
    EXPECT_EQ(run.get<std::int64_t>("Main.d"), 2);         // 1.5 ns
    EXPECT_EQ(run.get<std::int64_t>("Main.e"), 2);         // 2.5 ns
    EXPECT_EQ(run.get<std::int64_t>("Main.f"), 2);         // 1.5 ns
    EXPECT_EQ(run.get<std::int64_t>("Main.g"), 4);         // 3.5 ns
    EXPECT_EQ(run.get<std::int64_t>("Main.h"), 4);         // 3.5 ns
    EXPECT_EQ(run.get<std::int64_t>("Main.i"), 2'000'000); // 2.5 ms, TIME's unit as a number
    EXPECT_EQ(run.get<std::int64_t>("Main.j"), 2);         // 2.5 ns
}

TEST(RealToDurationRounding, ALiteralsFractionRoundsTiesToEven) {
    StProgram run(R"(PROGRAM Main
VAR a : TIME := T#2.5ns; b : TIME := T#3.5ns; c : LTIME := LTIME#-2.5ns;
    d : TIME := T#1s0.5ns; e : TOD := TOD#00:00:00.0000000025;
    f : TOD := TOD#00:00:01.0000000035; g : TIME := T#0.0025us; END_VAR
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(run.get<std::int64_t>("Main.a"), 2);
    EXPECT_EQ(run.get<std::int64_t>("Main.b"), 4);
    EXPECT_EQ(run.get<std::int64_t>("Main.c"), -2);
    EXPECT_EQ(run.get<std::int64_t>("Main.d"), 1'000'000'000);
    EXPECT_EQ(run.get<std::int64_t>("Main.e"), 2);
    EXPECT_EQ(run.get<std::int64_t>("Main.f"), 1'000'000'004);
    EXPECT_EQ(run.get<std::int64_t>("Main.g"), 2);
}

TEST(RealToDurationRounding, TextReadAsADurationRoundsTiesToEvenAsALiteralDoes) {
    StProgram run(R"(PROGRAM Main
VAR a, b, c, d : TIME; e : TOD; f : LTIME; END_VAR
a := STRING_TO_TIME('T#2.5ns'); b := STRING_TO_TIME('T#3.5ns'); c := STRING_TO_TIME('T#-2.5ns');
d := STRING_TO_TIME('T#1s0.5ns'); e := STRING_TO_TOD('TOD#00:00:01.0000000035');
f := STRING_TO_LTIME('LTIME#0.0025us');
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int64_t>("Main.a"), 2);
    EXPECT_EQ(run.get<std::int64_t>("Main.b"), 4);
    EXPECT_EQ(run.get<std::int64_t>("Main.c"), -2);
    EXPECT_EQ(run.get<std::int64_t>("Main.d"), 1'000'000'000);
    EXPECT_EQ(run.get<std::int64_t>("Main.e"), 1'000'000'004);
    EXPECT_EQ(run.get<std::int64_t>("Main.f"), 2);
}

} // namespace
} // namespace eposp::compiler::test
