// The reference evaluator follows the shift count rule of docs/st-language.md: the count taken
// as unsigned whatever its type (a negative one as its two's complement); SHL and SHR by at
// least the width give 0, ROL and ROR rotate by the count modulo the width.

#include "eposp/reference/reference_program.hpp"

#include <gtest/gtest.h>

namespace eposp::reference {
namespace {

TEST(ReferenceShiftCount, WideAndNegativeCountsFollowTheDocumentedRule) {
    ReferenceProgram program(R"(PROGRAM Main
VAR big : LINT := 4294967297; top : ULINT := 9223372036854775808; minus : SINT := -1;
    a, b, c, d, e, f : DWORD; g, h : LWORD; i, j : BYTE; END_VAR
a := SHL(DWORD#1, big); b := ROL(DWORD#1, big); c := SHR(DWORD#16#80000000, big);
d := ROR(DWORD#1, big); e := SHL(DWORD#1, minus); f := ROL(DWORD#1, minus);
g := SHL(LWORD#1, top); h := ROL(LWORD#1, top - 1); i := ROR(BYTE#1, minus);
j := SHR(BYTE#16#80, minus);
END_PROGRAM
)");
    ASSERT_TRUE(program.ok()) << program.errors();
    ASSERT_TRUE(program.scans(1)) << program.fault();
    EXPECT_EQ(program.bits("Main.a"), 0u);
    EXPECT_EQ(program.bits("Main.b"), 2u);
    EXPECT_EQ(program.bits("Main.c"), 0u);
    EXPECT_EQ(program.bits("Main.d"), 0x80000000u);
    EXPECT_EQ(program.bits("Main.e"), 0u);
    EXPECT_EQ(program.bits("Main.f"), 0x80000000u); // by 2^64 - 1, modulo 32: 31
    EXPECT_EQ(program.bits("Main.g"), 0u);
    EXPECT_EQ(program.bits("Main.h"), 0x8000000000000000u); // by 2^63 - 1, modulo 64: 63
    EXPECT_EQ(program.bits("Main.i"), 0x02u);               // ROR by 7 is ROL by 1
    EXPECT_EQ(program.bits("Main.j"), 0u);
}

} // namespace
} // namespace eposp::reference
