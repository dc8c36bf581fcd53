// The typing stage: an untyped literal takes the type its context needs (IEC 61131-3 ed. 3,
// 6.3.3); with no context an integer is a DINT (a LINT when it does not fit), a real an LREAL.

#include "typing_helpers.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(TypingLiterals, AnUntypedLiteralTakesTheTypeOfItsTarget) {
    const auto t = type_body("i : INT; r : REAL; w : BYTE; l : LREAL;",
                             "i := 5; r := 1; w := 16#FF; l := 2.5; r := 2.5;");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(t->type_of(0), "INT");
    EXPECT_EQ(t->type_of(1), "REAL");
    EXPECT_EQ(t->type_of(2), "BYTE");
    EXPECT_EQ(t->type_of(3), "LREAL");
    EXPECT_EQ(t->type_of(4), "REAL");
}

TEST(TypingLiterals, WithoutContextIntegersAreDintOrLintAndRealsLreal) {
    const auto t = type_body("b : BOOL;", "b := 5 > 3000000000; b := 1.5 > 1.0;");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    const auto& compare = std::get<ast::BinaryExpression>(t->value(0).node);
    EXPECT_EQ(t->program().type_of(*compare.left)->name, "LINT"); // takes the other side's type
    EXPECT_EQ(t->program().type_of(*compare.right)->name, "LINT");
    const auto& reals = std::get<ast::BinaryExpression>(t->value(1).node);
    EXPECT_EQ(t->program().type_of(*reals.left)->name, "LREAL");
}

TEST(TypingLiterals, ATypedLiteralKeepsItsTypeAndIsFolded) {
    const auto t = type_body("u : ULINT; d : DINT; s : STRING[5];",
                             "u := ULINT#9542150923762281093; d := -7; s := 'abc';");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(t->type_of(0), "ULINT");
    EXPECT_EQ(std::get<std::uint64_t>(*t->program().constant_of(t->value(0))),
              9542150923762281093U);
    EXPECT_EQ(std::get<std::int64_t>(*t->program().constant_of(t->value(1))), -7);
    EXPECT_EQ(t->type_of(2), "STRING[5]");
    EXPECT_EQ(std::get<std::string>(*t->program().constant_of(t->value(2))), "abc");
}

// A text takes the capacity of the STRING it goes to where it fits (code generation stores it
// in one copy), else its own length; NULL takes the reference it goes to, on either side of a
// comparison (issue 17).
TEST(TypingLiterals, ATextOrNullTakesTheTypeItGoesTo) {
    const auto t = type_body("s : STRING[5]; w : WSTRING[4]; b : BOOL; p : REF_TO INT;",
                             "s := 'abc'; s := 'abcdef'; w := \"ab\"; b := 'ab' = s; p := NULL; "
                             "b := NULL = p;");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(t->type_of(0), "STRING[5]");
    EXPECT_EQ(t->type_of(1), "STRING[6]"); // cut where it is stored (W0406)
    EXPECT_EQ(t->type_of(2), "WSTRING[4]");
    const auto& text = std::get<ast::BinaryExpression>(t->value(3).node);
    EXPECT_EQ(t->program().type_of(*text.left)->name, "STRING[5]");
    EXPECT_EQ(t->type_of(4), "REF_TO INT");
    const auto& null = std::get<ast::BinaryExpression>(t->value(5).node);
    EXPECT_EQ(t->program().type_of(*null.left)->name, "REF_TO INT");
}

// No value is a STRING[0] (issue 17): an empty literal without a STRING to go to is a
// STRING[1], and a selection of empty literals alone has a type code generation can lay out.
TEST(TypingLiterals, AnEmptyStringIsAStringOfOne) {
    const auto t =
        type_body("s : STRING; w : WSTRING; b : BOOL; i : INT;",
                  "b := '' = ''; b := \"\" = \"\"; s := SEL(b, '', ''); s := MAX('', ''); "
                  "s := MUX(i, 'a', '', 'abc'); s := '';");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    const auto operand = [&](int statement) {
        return t->program()
            .type_of(*std::get<ast::BinaryExpression>(t->value(statement).node).left)
            ->name;
    };
    EXPECT_EQ(operand(0), "STRING[1]");
    EXPECT_EQ(operand(1), "WSTRING[1]");
    EXPECT_EQ(t->type_of(2), "STRING[1]");
    EXPECT_EQ(t->type_of(3), "STRING[1]");
    EXPECT_EQ(t->type_of(4), "STRING[3]");
    EXPECT_EQ(t->type_of(5), "STRING[80]"); // the STRING it goes to
}

TEST(TypingLiterals, AConstantIsFoldedWhereItIsUsed) {
    const auto t = type_source("PROGRAM Main\nVAR CONSTANT k : INT := 42; END_VAR\n"
                               "VAR x : INT; END_VAR\nx := k;\nEND_PROGRAM\n");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(std::get<std::int64_t>(*t->program().constant_of(t->value(0))), 42);
}

// A CONSTANT has the value its own type computes for its initial value, by the one evaluator
// that gives initial values and bounds theirs: a REAL one in single precision (it was the
// LREAL 0.1), one defined by arithmetic too (it had none), a DINT's least value as a sum (issue
// 17; one beyond DINT's range is E0311, types_initial_value_ranges.st).
TEST(TypingLiterals, AConstantHasTheValueItsOwnTypeComputes) {
    const auto t = type_source("PROGRAM Main\nVAR CONSTANT r : REAL := 0.1; k : INT := 2 * 3;\n"
                               "w : DINT := -2147483647 - 1; END_VAR\n"
                               "VAR x : LREAL; i : INT; d : DINT; y : REAL; END_VAR\n"
                               "x := r; i := k; d := w; y := 0.1;\nEND_PROGRAM\n");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    for (int i = 0; i < 4; ++i) {
        ASSERT_NE(t->program().constant_of(t->value(i)), nullptr) << i;
    }
    EXPECT_EQ(std::get<double>(*t->program().constant_of(t->value(0))), static_cast<double>(0.1F));
    EXPECT_EQ(std::get<std::int64_t>(*t->program().constant_of(t->value(1))), 6);
    EXPECT_EQ(std::get<std::int64_t>(*t->program().constant_of(t->value(2))), INT32_MIN);
    EXPECT_EQ(std::get<double>(*t->program().constant_of(t->value(3))), static_cast<double>(0.1F));
}

TEST(TypingLiterals, ADirectAddressHasTheTypeOfItsSize) {
    const auto t =
        type_body("w : WORD; b : BOOL; d : DWORD;", "w := %IW4; b := %IX0.1; d := %MD8;");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(t->type_of(0), "WORD");
    EXPECT_EQ(t->type_of(1), "BOOL");
    EXPECT_EQ(t->type_of(2), "DWORD");
}

TEST(TypingLiterals, ALiteralThatDoesNotFitItsContextKeepsItsOwnType) {
    const auto t = type_body("i : INT;", "i := 70000;");
    EXPECT_FALSE(t->front_end->program);
    EXPECT_NE(t->errors().find("the value 70000 does not fit in INT [E0311]"), std::string::npos)
        << t->errors();
}

} // namespace
} // namespace eposp::compiler::test
