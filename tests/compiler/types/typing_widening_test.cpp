// The typing stage: implicit conversions only widen (IEC 61131-3 ed. 3, figure 11); the operands
// of an operator meet in the smallest type both widen to.

#include "typing_helpers.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(TypingWidening, OperandsMeetInTheSmallestCommonType) {
    const auto t = type_body("i : INT; d : DINT; ud : UDINT; s : SINT; us : USINT; r : REAL; "
                             "l : LREAL; li : LINT; n : INT; w : WORD; b : BYTE; dw : DWORD;",
                             "d := i + d; li := ud + d; n := s + us; l := r * l; dw := w AND b;");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(t->type_of(0), "DINT");
    EXPECT_EQ(t->type_of(1), "LINT"); // UDINT and DINT both widen to LINT
    EXPECT_EQ(t->type_of(2), "INT");
    EXPECT_EQ(t->type_of(3), "LREAL");
    EXPECT_EQ(t->type_of(4), "WORD");
}

TEST(TypingWidening, NarrowingAssignmentsAreErrors) {
    const auto t = type_body("i : INT; d : DINT; r : REAL;", "i := d;\nr := d;");
    EXPECT_FALSE(t->front_end->program);
    EXPECT_NE(t->errors().find("test.st:5:6: error: a value of type INT is expected, not DINT"),
              std::string::npos)
        << t->errors();
    // DINT widens to LREAL only (figure 11): a REAL cannot hold every DINT.
    EXPECT_NE(t->errors().find("a value of type REAL is expected, not DINT"), std::string::npos)
        << t->errors();
}

TEST(TypingWidening, WideningAssignmentsAreAccepted) {
    const auto t = type_body("i : INT; d : DINT; r : REAL; l : LREAL; u : UINT; ul : ULINT;",
                             "d := i; r := i; l := d; d := u; ul := u;");
    EXPECT_TRUE(t->front_end->program) << t->errors();
}

TEST(TypingWidening, OperandsWithoutACommonTypeAreAnError) {
    const auto t = type_body("b : BOOL; i : INT; x : INT;", "x := i + b;");
    EXPECT_FALSE(t->front_end->program);
    EXPECT_NE(t->errors().find("INT and BOOL have no common type"), std::string::npos)
        << t->errors();
}

} // namespace
} // namespace eposp::compiler::test
