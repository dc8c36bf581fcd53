// SIZEOF of a type's name (issue 17): the size SIZEOF of a variable of that type gives (the
// VM's layout); and the formal call of the standard functions of one input IN, NOT(IN := w)
// as CODESYS writes it, which was a syntax error.

#include "codegen_harness.hpp"

#include <cstdint>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(SizeOfATypeName, IsTheSizeOfAVariableOfThatType) {
    StProgram run(
        R"(TYPE Axis : STRUCT position : LREAL; moving : BOOL; name : STRING[10]; END_STRUCT; END_TYPE
TYPE Mode : (Idle, Run) DINT; END_TYPE
FUNCTION_BLOCK Counter
VAR_INPUT up : BOOL; END_VAR
VAR count : LINT; END_VAR
count := count + 1;
END_FUNCTION_BLOCK
PROGRAM Main
VAR
    a : Axis; m : Mode; c : Counter; t : TON; s : STRING; w : WSTRING[7]; r : LREAL; i : INT;
    of_axis, of_a, of_mode, of_m, of_counter, of_c, of_ton, of_t : UDINT;
    of_string, of_s, of_w, of_lreal, of_int, of_bool : UDINT;
END_VAR
of_axis := SIZEOF(Axis);       of_a := SIZEOF(a);
of_mode := SIZEOF(Mode);       of_m := SIZEOF(m);
of_counter := SIZEOF(Counter); of_c := SIZEOF(c);
of_ton := SIZEOF(TON);         of_t := SIZEOF(t);
of_string := SIZEOF(STRING);   of_s := SIZEOF(s);
of_w := SIZEOF(w);
of_lreal := SIZEOF(LREAL);     of_int := SIZEOF(INT);      of_bool := SIZEOF(BOOL);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_axis"), run.get<std::uint32_t>("Main.of_a"));
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_mode"), run.get<std::uint32_t>("Main.of_m"));
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_mode"), 4U);
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_counter"), run.get<std::uint32_t>("Main.of_c"));
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_ton"), run.get<std::uint32_t>("Main.of_t"));
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_string"), run.get<std::uint32_t>("Main.of_s"));
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_lreal"), 8U);
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_int"), 2U);
    EXPECT_EQ(run.get<std::uint32_t>("Main.of_bool"), 1U);
}

TEST(SizeOfATypeName, AnUndeclaredNameIsStillUnknown) {
    EXPECT_NE(diagnostics_of(R"(PROGRAM Main
VAR n : UDINT; END_VAR
n := SIZEOF(Nothing);
END_PROGRAM
)")
                  .find("E0201"),
              std::string::npos);
}

TEST(FormalInputOfOneInputFunctions, NotAbsAndConversionsTakeIn) {
    StProgram run(R"(PROGRAM Main
VAR
    w : WORD := 16#00FF; flipped : WORD; on : BOOL; off : BOOL;
    i : INT := -5; magnitude : INT; wide : DINT; mixed : WORD;
END_VAR
flipped := NOT(IN := w);
off := NOT(IN := on OR TRUE);
magnitude := ABS(IN := i);
wide := INT_TO_DINT(IN := i);
mixed := NOT(IN := w) AND 16#0F0F;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::uint16_t>("Main.flipped"), 0xFF00);
    EXPECT_EQ(run.get<std::uint8_t>("Main.off"), 0);
    EXPECT_EQ(run.get<std::int16_t>("Main.magnitude"), 5);
    EXPECT_EQ(run.get<std::int32_t>("Main.wide"), -5);
    EXPECT_EQ(run.get<std::uint16_t>("Main.mixed"), 0x0F00);
}

// NOT's formal call takes EN and ENO beside IN, as every standard function's does.
TEST(FormalInputOfOneInputFunctions, NotTakesEnAndEno) {
    StProgram run(R"(PROGRAM Main
VAR
    w : WORD := 16#00FF; flipped : WORD; enabled : WORD;
    done : BOOL; skipped : BOOL := TRUE;
END_VAR
flipped := NOT(IN := w, ENO => done);
enabled := NOT(EN := FALSE, IN := w, ENO => skipped);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::uint16_t>("Main.flipped"), 0xFF00);
    EXPECT_EQ(run.get<std::uint8_t>("Main.done"), 1);
    EXPECT_EQ(run.get<std::uint8_t>("Main.skipped"), 0);
}

TEST(FormalInputOfOneInputFunctions, NotHasNoOtherInput) {
    EXPECT_NE(diagnostics_of(R"(PROGRAM Main
VAR w : WORD; END_VAR
w := NOT(X := w);
END_PROGRAM
)")
                  .find("E0210"),
              std::string::npos);
}

} // namespace
} // namespace eposp::compiler::test
