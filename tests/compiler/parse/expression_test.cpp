// Operators with the precedence and associativity of IEC 61131-3 ed. 3, table 71, and the
// postfix forms: member, bit, index, dereference, call.
#include "parse_helpers.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler {
namespace {

using test::expression_sexpr;

struct ExpressionCase {
    const char* name;
    const char* source;
    const char* expected;
};

void PrintTo(const ExpressionCase& c, std::ostream* out) {
    *out << c.source;
}

class ExpressionShape : public testing::TestWithParam<ExpressionCase> {};

TEST_P(ExpressionShape, FollowsIecPrecedence) {
    EXPECT_EQ(expression_sexpr(GetParam().source), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Table71, ExpressionShape,
    testing::Values(
        ExpressionCase{"MultiplyBeforeAdd", "a + b * c", "(+ (name a) (* (name b) (name c)))"},
        ExpressionCase{"SubtractIsLeftAssociative", "a - b - c",
                       "(- (- (name a) (name b)) (name c))"},
        ExpressionCase{"PowerIsLeftAssociative", "2 ** 3 ** 2",
                       "(** (** (int 2) (int 3)) (int 2))"},
        ExpressionCase{"NegationBindsTighterThanPower", "-x ** 2", "(** (neg (name x)) (int 2))"},
        ExpressionCase{"PowerBeforeMultiply", "a * b ** c", "(* (name a) (** (name b) (name c)))"},
        ExpressionCase{"ModLikeMultiply", "a MOD b + c", "(+ (MOD (name a) (name b)) (name c))"},
        ExpressionCase{"DivideLeftToRight", "a / b * c", "(* (/ (name a) (name b)) (name c))"},
        ExpressionCase{"NotBeforeAnd", "NOT a AND b", "(AND (NOT (name a)) (name b))"},
        ExpressionCase{"OrXorAnd", "a OR b XOR c AND d",
                       "(OR (name a) (XOR (name b) (AND (name c) (name d))))"},
        ExpressionCase{"AmpersandIsAnd", "a & b", "(AND (name a) (name b))"},
        ExpressionCase{"EqualityBelowComparison", "a < b = c >= d",
                       "(= (< (name a) (name b)) (>= (name c) (name d)))"},
        ExpressionCase{"ComparisonBelowAdd", "a + 1 <= b", "(<= (+ (name a) (int 1)) (name b))"},
        ExpressionCase{"AndBelowEquality", "a = b AND c <> d",
                       "(AND (= (name a) (name b)) (<> (name c) (name d)))"},
        ExpressionCase{"Parentheses", "(a + b) * c", "(* (+ (name a) (name b)) (name c))"},
        ExpressionCase{"NegativeLiteralBaseOfPower", "-2 ** 2", "(** (int -2) (int 2))"},
        ExpressionCase{"NegativeExponent", "a ** -b", "(** (name a) (neg (name b)))"},
        ExpressionCase{"NegativeLiteralExponent", "2 ** -1", "(** (int 2) (int -1))"},
        ExpressionCase{"NamesPowerIsLeftAssociative", "a ** b ** c",
                       "(** (** (name a) (name b)) (name c))"},
        ExpressionCase{"NegatedNegativeLiteral", "- - 1", "(neg (int -1))"},
        ExpressionCase{"NegatedOperandOfMultiply", "a * -b + c",
                       "(+ (* (name a) (neg (name b))) (name c))"},
        ExpressionCase{"SubtractNegated", "a - -b", "(- (name a) (neg (name b)))"},
        ExpressionCase{"NegationAppliesToTheMember", "-a.b", "(neg (member (name a) b))"},
        ExpressionCase{"NotBeforeEquality", "NOT a = b", "(= (NOT (name a)) (name b))"},
        ExpressionCase{"NotOfACall", "NOT f(x)", "(NOT (call (name f) (name x)))"},
        ExpressionCase{"ComparisonsChainLeftToRight", "a < b < c",
                       "(< (< (name a) (name b)) (name c))"},
        ExpressionCase{"EqualitiesChainLeftToRight", "a = b <> c",
                       "(<> (= (name a) (name b)) (name c))"},
        ExpressionCase{"XorBelowAnd", "a XOR b AND c", "(XOR (name a) (AND (name b) (name c)))"},
        ExpressionCase{"OrLeftToRight", "a OR b OR c", "(OR (OR (name a) (name b)) (name c))"},
        ExpressionCase{"PostfixChain", "f(x)[1]^.y",
                       "(member (deref (index (call (name f) (name x)) (int 1))) y)"},
        ExpressionCase{"ParenthesizedLiteralNegated", "-(2)", "(int -2)"},
        ExpressionCase{"OperatorAsFunction", "MOD(a, b) + 1",
                       "(+ (call (name MOD) (name a) (name b)) (int 1))"},
        ExpressionCase{"UnaryPlus", "+a", "(plus (name a))"},
        ExpressionCase{"DoubleNot", "NOT NOT a", "(NOT (NOT (name a)))"},
        ExpressionCase{"CaseInsensitiveOperators", "a and b or not c",
                       "(OR (AND (name a) (name b)) (NOT (name c)))"},
        ExpressionCase{"MemberIndexBit", "arr[i, j + 1].field.3",
                       "(bit (member (index (name arr) (name i) (+ (name j) (int 1))) field) 3)"},
        ExpressionCase{"Dereference", "p^.x", "(member (deref (name p)) x)"},
        ExpressionCase{"Ref", "REF(x)", "(ref (name x))"},
        ExpressionCase{"Adr", "ADR(x)", "(call (name ADR) (name x))"},
        ExpressionCase{"Sizeof", "SIZEOF(INT)", "(call (name SIZEOF) (name INT))"},
        ExpressionCase{"CallMixedArguments", "LIMIT(lo, x, hi)",
                       "(call (name LIMIT) (name lo) (name x) (name hi))"},
        ExpressionCase{"CallFormalArguments", "f(a := 1, b := x + 1)",
                       "(call (name f) a:=(int 1) b:=(+ (name x) (int 1)))"},
        ExpressionCase{"CallWithoutArguments", "f()", "(call (name f))"},
        ExpressionCase{
            "FbOutput", "fb.Q AND ton1.ET > T#1s",
            "(AND (member (name fb) Q) (> (member (name ton1) ET) (TIME 1000000000ns)))"}),
    [](const auto& c) { return std::string(c.param.name); });

TEST(Expression, RangeCoversTheWholeExpression) {
    const test::Parsed parsed = test::parse_text("PROGRAM P\nx := a + b * c;\nEND_PROGRAM\n");
    ASSERT_FALSE(parsed.diagnostics.has_errors()) << parsed.rendered();
    const auto& assignment =
        std::get<ast::AssignmentStatement>(parsed.unit.pous.front().body.front().node);
    EXPECT_EQ(assignment.value->range.begin, (SourcePosition{2, 6}));
    EXPECT_EQ(assignment.value->range.end, (SourcePosition{2, 14}));
    EXPECT_EQ(parsed.unit.pous.front().body.front().range.end, (SourcePosition{2, 15}));
}

TEST(Expression, MissingOperandIsReported) {
    EXPECT_EQ(test::statement_error("x := a + ;"), "expected an expression, found ';'");
}

// What may follow a '.': a member's name or a bit number, not the postfix operators.
TEST(Expression, MissingMemberIsReported) {
    EXPECT_EQ(test::statement_error("x := a. ;"), "expected an integer or a name, found ';'");
    EXPECT_EQ(test::statement_error("x := a.DO;"), "expected an integer or a name, found 'DO'");
}

} // namespace
} // namespace eposp::compiler
