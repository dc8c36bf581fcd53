// The typing stage: what each call calls, the overload of a generic (ANY_*) standard function,
// conversions and user POUs with formal, positional, output and VAR_IN_OUT arguments.

#include "typing_helpers.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

TEST(TypingCalls, GenericFunctionsTakeTheCommonTypeOfTheirInputs) {
    const auto t =
        type_body("i : INT; d : DINT; s : STRING[5]; u : STRING[7]; x : DINT; "
                  "y : STRING[20]; g : BOOL; n : INT;",
                  "x := MAX(i, d, 3); y := MIN(s, u); y := SEL(IN1 := u, G := g, "
                  "IN0 := s); n := LEN(u); y := CONCAT(s, u, 'ab'); y := SEL(g, u, 'a');");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    const types::CallTarget* max = t->program().call_target(t->value(0));
    ASSERT_NE(max, nullptr);
    EXPECT_EQ(max->kind, types::CallKind::StandardFunction);
    EXPECT_EQ(max->name, "MAX");
    EXPECT_EQ(max->operand->name, "DINT");
    EXPECT_EQ(t->type_of(1), "STRING[7]");
    EXPECT_EQ(t->type_of(2), "STRING[7]"); // formal inputs in any order
    EXPECT_EQ(t->type_of(3), "INT");
    EXPECT_EQ(t->type_of(4), "STRING[14]"); // CONCAT holds every input
    EXPECT_EQ(t->type_of(5), "STRING[7]");  // the longest input, not the last
}

// SIZEOF is a constant the typing stage knows, of the smallest unsigned type holding it
// (CODESYS); a string function's result holds what its inputs make (issue 17).
TEST(TypingCalls, SizeofIsAConstantAndTextResultsHoldTheirInputs) {
    const auto t = type_body("a : ARRAY[1..10] OF DINT; b : ARRAY[0..99] OF LREAL; "
                             "c : ARRAY[0..9999] OF LREAL; x : UDINT; s : STRING[5]; "
                             "y : STRING[80];",
                             "x := SIZEOF(a); x := SIZEOF(b); x := SIZEOF(c); "
                             "y := CONCAT(s, ''); y := LEFT(s, 2);");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(t->type_of(0), "USINT");
    EXPECT_EQ(std::get<std::uint64_t>(*t->program().constant_of(t->value(0))), 40U);
    EXPECT_EQ(t->type_of(1), "UINT");
    EXPECT_EQ(std::get<std::uint64_t>(*t->program().constant_of(t->value(1))), 800U);
    EXPECT_EQ(t->type_of(2), "UDINT");
    EXPECT_EQ(std::get<std::uint64_t>(*t->program().constant_of(t->value(2))), 80000U);
    EXPECT_EQ(t->type_of(3), "STRING[6]");
    EXPECT_EQ(t->type_of(4), "STRING[5]");
}

TEST(TypingCalls, ConversionsNameTheirSourceAndResult) {
    const auto t = type_body("d : DINT; ud : UDINT; r : REAL; x : DINT; l : LINT;",
                             "ud := DINT_TO_UDINT(d); x := TRUNC(r); l := TO_LINT(ud);");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    const types::CallTarget* convert = t->program().call_target(t->value(0));
    ASSERT_NE(convert, nullptr);
    EXPECT_EQ(convert->kind, types::CallKind::Conversion);
    EXPECT_EQ(convert->operand->name, "DINT");
    EXPECT_EQ(convert->result->name, "UDINT");
    EXPECT_EQ(t->type_of(1), "DINT");
    EXPECT_EQ(t->program().call_target(t->value(2))->operand->name, "UDINT");
}

TEST(TypingCalls, UserFunctionsAndFunctionBlocks) {
    const auto t = type_source(R"(
FUNCTION Scale : REAL
  VAR_INPUT v : REAL; k : REAL := 2.0; END_VAR
  VAR_OUTPUT clipped : BOOL; END_VAR
  VAR_IN_OUT log : INT; END_VAR
  Scale := v * k;
END_FUNCTION
PROGRAM Main
  VAR r : REAL; c : BOOL; n : INT; t : TON; done : BOOL; END_VAR
  r := Scale(1.5, 3, n);
  r := Scale(v := 1, clipped => c, log := n);
  t(IN := TRUE, PT := T#1s, Q => done);
END_PROGRAM
)");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    const types::CallTarget* scale = t->program().call_target(t->value(0));
    ASSERT_NE(scale, nullptr);
    EXPECT_EQ(scale->kind, types::CallKind::Function);
    EXPECT_EQ(scale->pou->name.name, "Scale");
    EXPECT_EQ(scale->result->name, "REAL");
    const auto& call = std::get<ast::CallExpression>(t->value(0).node);
    EXPECT_EQ(t->program().type_of(*call.arguments[1].value)->name, "REAL"); // 3 as a REAL
    const ast::Pou& main = t->front_end->units.back().pous.back();
    const auto& ton = *std::get<ast::CallStatement>(main.body[2].node).call;
    const types::CallTarget* timer = t->program().call_target(ton);
    ASSERT_NE(timer, nullptr);
    EXPECT_EQ(timer->kind, types::CallKind::StandardFunctionBlock);
    EXPECT_EQ(timer->name, "TON");
}

TEST(TypingCalls, ArgumentsOfTheWrongTypeAreErrors) {
    const auto t = type_source(R"(
FUNCTION F : INT
  VAR_INPUT a : INT; END_VAR
  VAR_IN_OUT b : INT; END_VAR
  F := a + b;
END_FUNCTION
PROGRAM Main
  VAR d : DINT; x : INT; END_VAR
  x := F(d, d);
END_PROGRAM
)");
    EXPECT_FALSE(t->front_end->program);
    EXPECT_NE(t->errors().find("a DINT value cannot be used as INT"), std::string::npos)
        << t->errors();
    EXPECT_NE(t->errors().find("VAR_IN_OUT 'b' needs a INT variable [E0302]"), std::string::npos)
        << t->errors();
}

TEST(TypingCalls, MaxMinAndLimitAcceptStrings) {
    const auto t = type_body("a, b : STRING; x : STRING;", "x := LIMIT(a, 'm', b);");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    EXPECT_EQ(t->type_of(0), "STRING[80]");
}

TEST(TypingCalls, TheBuiltInLibraryPousAreTypedToo) {
    // Code generation generates TON's body from the library source and reads its types here.
    const auto t = type_body("t : TON;", "t(IN := TRUE, PT := T#1s);");
    ASSERT_TRUE(t->front_end->program) << t->errors();
    const ast::Pou* ton = t->front_end->library_pou("TON");
    ASSERT_NE(ton, nullptr);
    const auto& outer = std::get<ast::IfStatement>(ton->body[0].node).branches[0];
    EXPECT_EQ(t->program().type_of(*outer.condition)->name, "BOOL"); // IN
    const auto& elapsed = std::get<ast::AssignmentStatement>(outer.body[1].node);
    EXPECT_EQ(t->program().type_of(*elapsed.value)->name, "TIME"); // CURRENT_TIME() - start
    const auto& difference = std::get<ast::BinaryExpression>(elapsed.value->node);
    const types::CallTarget* now = t->program().call_target(*difference.left);
    ASSERT_NE(now, nullptr);
    EXPECT_EQ(now->pou->name.name, "CURRENT_TIME");
}

} // namespace
} // namespace eposp::compiler::test
