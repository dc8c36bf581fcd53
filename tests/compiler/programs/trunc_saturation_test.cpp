// TRUNC rounds toward zero into DINT and, like every *_TO_* conversion of a real, saturates a
// value beyond DINT's range at its nearest limit (NaN gives 0) instead of wrapping it.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(TruncSaturation, AValueBeyondDintGivesItsNearestLimit) {
    StProgram run(R"(PROGRAM Main
VAR big : LREAL := 1.0E10; r : REAL := -3.0E9; zero : LREAL;
    a, b, c, d, e, f, g, h : DINT; END_VAR
a := TRUNC(1.0E10); b := TRUNC(big); c := TRUNC(r); d := TRUNC(-big);
e := TRUNC(2147483647.9); f := TRUNC(-2147483648.9); g := TRUNC(zero / zero);
h := TRUNC(REAL#-1.0E30);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.a"), 2147483647);
    EXPECT_EQ(run.get<std::int32_t>("Main.b"), 2147483647);
    EXPECT_EQ(run.get<std::int32_t>("Main.c"), -2147483647 - 1);
    EXPECT_EQ(run.get<std::int32_t>("Main.d"), -2147483647 - 1);
    EXPECT_EQ(run.get<std::int32_t>("Main.e"), 2147483647);
    EXPECT_EQ(run.get<std::int32_t>("Main.f"), -2147483647 - 1);
    EXPECT_EQ(run.get<std::int32_t>("Main.g"), 0);
    EXPECT_EQ(run.get<std::int32_t>("Main.h"), -2147483647 - 1);
}

TEST(TruncSaturation, AValueInsideDintStaysTruncated) {
    StProgram run(R"(PROGRAM Main
VAR a, b, c, d, e, f : DINT; x : LREAL := -2147483647.5; r : REAL := 2.5; l : LREAL := -3.7;
END_VAR
a := TRUNC(2.5); b := TRUNC(-3.7); c := TRUNC(x); d := TRUNC(r); e := TRUNC(l);
f := TRUNC(3.5);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.a"), 2);
    EXPECT_EQ(run.get<std::int32_t>("Main.b"), -3);
    EXPECT_EQ(run.get<std::int32_t>("Main.c"), -2147483647);
    EXPECT_EQ(run.get<std::int32_t>("Main.d"), 2); // a REAL variable as an LREAL one
    EXPECT_EQ(run.get<std::int32_t>("Main.e"), -3);
    EXPECT_EQ(run.get<std::int32_t>("Main.f"), 3); // toward zero, not to even
}

} // namespace
} // namespace eposp::compiler::test
