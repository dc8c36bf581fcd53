// The typing stage: implicit conversions only widen (IEC 61131-3 ed. 3, figure 11); the operands
// of an operator meet in the type of the one the other widens to.

#include "typing_helpers.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(TypingWidening, OperandsMeetInTheTypeTheOtherWidensTo) {
    const auto t = type_body("i : INT; d : DINT; r : REAL; "
                             "l : LREAL; w : WORD; b : BYTE; dw : DWORD;",
                             "d := i + d; l := r * l; dw := w AND b;");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(t->type_of(0), "DINT");
    EXPECT_EQ(t->type_of(1), "LREAL");
    EXPECT_EQ(t->type_of(2), "WORD");
}

TEST(TypingWidening, OperandsOfWhichNeitherWidensToTheOtherAreAnError) {
    // As code generation always did (and the E0303 example of the catalogue): no third type is
    // sought that both would widen to; the program converts one of them.
    const auto t = type_body("ud : UDINT; d : DINT; s : SINT; us : USINT; li : LINT; n : INT;",
                             "li := ud + d; n := s + us;");
    EXPECT_FALSE(t->front_end->program);
    EXPECT_NE(t->errors().find("test.st:5:7: error: operands of types UDINT and DINT do not match "
                               "[E0303]"),
              std::string::npos)
        << t->errors();
    EXPECT_NE(t->errors().find("operands of types SINT and USINT do not match [E0303]"),
              std::string::npos)
        << t->errors();
}

TEST(TypingWidening, NarrowingAssignmentsAreErrors) {
    const auto t = type_body("i : INT; d : DINT; r : REAL;", "i := d;\nr := d;");
    EXPECT_FALSE(t->front_end->program);
    EXPECT_NE(
        t->errors().find("test.st:5:6: error: a DINT value cannot be used as INT (convert it with "
                         "DINT_TO_INT) [E0301]"),
        std::string::npos)
        << t->errors();
    // DINT widens to LREAL only (figure 11): a REAL cannot hold every DINT.
    EXPECT_NE(t->errors().find("a DINT value cannot be used as REAL"), std::string::npos)
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
    EXPECT_NE(t->errors().find("operands of types INT and BOOL do not match [E0303]"),
              std::string::npos)
        << t->errors();
}

} // namespace
} // namespace eposp::compiler::test
