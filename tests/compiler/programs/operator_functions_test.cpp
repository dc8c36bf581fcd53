// The operators of IEC 61131-3 ed. 3 tables 29 and 30 are functions as well: MOD, AND, OR and
// XOR are keywords, yet `MOD(a, b)` and `AND(a, b, c)` call them as ADD(...) and DIV(...) are
// called, positionally or with named inputs, and give what the operator gives. NOT(x) is the
// operator NOT applied to (x), the same value.
#include "codegen_harness.hpp"

#include <cstdint>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(OperatorFunctions, EveryArithmeticAndLogicalOperatorCanBeCalled) {
    StProgram run(R"(PROGRAM Main
VAR y : DINT := -17; z : DINT := 5; w : WORD := 16#F0F0; p, q : BOOL := TRUE;
    m, m2, m3, s, a, u, d : DINT; e : LREAL; x1, x2, x3, x4 : WORD; b1, b2, b3, b4, b5 : BOOL; END_VAR
m := MOD(y, z); m2 := mod(IN1 := 17, IN2 := z) + 1; s := ADD(y, z, 1); a := SUB(y, z);
u := MUL(y, z); d := DIV(y, z); e := EXPT(LREAL#1.5, 2);
x1 := AND(w, 16#FF00, 16#3FFF); x2 := OR(w, 16#000F); x3 := XOR(w, 16#FFFF); x4 := NOT(w);
m3 := y MOD(z); b5 := FALSE OR(p) AND(FALSE); (* still the operators *)
b1 := AND(p, NOT q); b2 := OR(p, FALSE) AND NOT(q); b3 := XOR(p, q, TRUE); b4 := NOT(p);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.m"), -2);
    EXPECT_EQ(run.get<std::int32_t>("Main.m2"), 3);
    EXPECT_EQ(run.get<std::int32_t>("Main.s"), -11);
    EXPECT_EQ(run.get<std::int32_t>("Main.a"), -22);
    EXPECT_EQ(run.get<std::int32_t>("Main.u"), -85);
    EXPECT_EQ(run.get<std::int32_t>("Main.d"), -3);
    EXPECT_EQ(run.get<double>("Main.e"), 2.25);
    EXPECT_EQ(run.get<std::uint16_t>("Main.x1"), 0x3000u);
    EXPECT_EQ(run.get<std::uint16_t>("Main.x2"), 0xF0FFu);
    EXPECT_EQ(run.get<std::uint16_t>("Main.x3"), 0x0F0Fu);
    EXPECT_EQ(run.get<std::uint16_t>("Main.x4"), 0x0F0Fu);
    EXPECT_FALSE(run.get<bool>("Main.b1"));
    EXPECT_FALSE(run.get<bool>("Main.b2"));
    EXPECT_TRUE(run.get<bool>("Main.b3"));
    EXPECT_FALSE(run.get<bool>("Main.b4"));
    EXPECT_EQ(run.get<std::int32_t>("Main.m3"), -2);
    EXPECT_FALSE(run.get<bool>("Main.b5"));
}

TEST(OperatorFunctions, AConstantZeroDivisorOfModIsAnErrorAsForTheOperator) {
    EXPECT_NE(diagnostics_of("PROGRAM Main VAR x, y : DINT; END_VAR x := MOD(y, 0); END_PROGRAM")
                  .find("MOD by zero"),
              std::string::npos);
}

} // namespace
} // namespace eposp::compiler::test
