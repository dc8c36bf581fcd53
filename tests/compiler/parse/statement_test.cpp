// Statements of IEC 61131-3 ed. 3, 7.3.3 (table 72).
#include "parse_helpers.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler {
namespace {

using test::statement_error;
using test::statements_sexpr;

TEST(Statement, Assignment) {
    EXPECT_EQ(statements_sexpr("x := 1;"), "(assign (name x) (int 1))");
}

TEST(Statement, AssignmentToElementAndDereference) {
    EXPECT_EQ(statements_sexpr("a[i].b := 1; p^ := 2; w.0 := TRUE;"),
              "(assign (member (index (name a) (name i)) b) (int 1)) "
              "(assign (deref (name p)) (int 2)) (assign (bit (name w) 0) (bool TRUE))");
}

TEST(Statement, FbCallWithInputsAndOutputs) {
    EXPECT_EQ(statements_sexpr("fb(IN := x, PT := T#1s, Q => y, NOT Q2 => z);"),
              "(call (name fb) IN:=(name x) PT:=(TIME 1000000000ns) Q=>(name y) "
              "NOT Q2=>(name z))");
}

TEST(Statement, CallWithEnAndEno) {
    EXPECT_EQ(statements_sexpr("ADD(EN := go, IN1 := a, IN2 := b, ENO => ok);"),
              "(call (name ADD) EN:=(name go) IN1:=(name a) IN2:=(name b) ENO=>(name ok))");
}

TEST(Statement, IfElsifElse) {
    EXPECT_EQ(statements_sexpr("IF a THEN x := 1; ELSIF b THEN x := 2; ELSIF c THEN ; ELSE x := 3; "
                               "END_IF;"),
              "(if (name a) (then (assign (name x) (int 1))) (name b) (then (assign (name x) "
              "(int 2))) (name c) (then (empty)) (else (assign (name x) (int 3))))");
}

TEST(Statement, CaseWithListsRangesEnumsAndElse) {
    EXPECT_EQ(statements_sexpr("CASE s OF 1, 2: x := 1; 3..5: x := 2; Color#Red: x := 3; Idle: "
                               "x := 4; y := 5; ELSE x := 0; END_CASE;"),
              "(case (name s) ((int 1) (int 2) (: (assign (name x) (int 1)))) ((int 3)..(int 5) "
              "(: (assign (name x) (int 2)))) ((enum Color Red) (: (assign (name x) (int 3)))) "
              "((name Idle) (: (assign (name x) (int 4)) (assign (name y) (int 5)))) (else "
              "(assign (name x) (int 0))))");
}

TEST(Statement, CaseWithNegativeLabels) {
    EXPECT_EQ(statements_sexpr("CASE s OF -1: x := 1; -5..-2: x := 2; END_CASE;"),
              "(case (name s) ((int -1) (: (assign (name x) (int 1)))) ((int -5)..(int -2) (: "
              "(assign (name x) (int 2)))))");
}

TEST(Statement, ForWithAndWithoutBy) {
    EXPECT_EQ(statements_sexpr("FOR i := 10 TO 0 BY -2 DO EXIT; END_FOR; FOR i := 1 TO n DO "
                               "CONTINUE; END_FOR;"),
              "(for i (int 10) (int 0) (int -2) (do (exit))) (for i (int 1) (name n) (do "
              "(continue)))");
}

TEST(Statement, WhileAndRepeat) {
    EXPECT_EQ(statements_sexpr("WHILE i < 10 DO i := i + 1; END_WHILE; REPEAT i := i - 1; UNTIL i "
                               "= 0 END_REPEAT;"),
              "(while (< (name i) (int 10)) (do (assign (name i) (+ (name i) (int 1))))) (repeat "
              "(do (assign (name i) (- (name i) (int 1)))) (= (name i) (int 0)))");
}

TEST(Statement, ReturnAndEmpty) {
    EXPECT_EQ(statements_sexpr("RETURN; ;"), "(return) (empty)");
}

TEST(Statement, KeywordsAreCaseInsensitive) {
    EXPECT_EQ(statements_sexpr("if a then x := 1; Elsif b THEN x := 2; end_if;"),
              "(if (name a) (then (assign (name x) (int 1))) (name b) (then (assign (name x) "
              "(int 2))))");
}

TEST(Statement, SemicolonAfterEndKeywordsMayBeOmitted) {
    EXPECT_EQ(statements_sexpr("IF a THEN x := 1; END_IF WHILE b DO ; END_WHILE y := 2;"),
              "(if (name a) (then (assign (name x) (int 1)))) (while (name b) (do (empty))) "
              "(assign (name y) (int 2))");
}

TEST(Statement, DirectlyAddressedVariablesInCode) {
    EXPECT_EQ(statements_sexpr("%QX1.0 := %IX0.7 AND NOT %MX3.1;"),
              "(assign (at %QX1.0) (AND (at %IX0.7) (NOT (at %MX3.1))))");
}

TEST(Statement, CommentsAndPragmasAreSkipped) {
    EXPECT_EQ(statements_sexpr("(* a (* nested *) comment *) x := 1; // line\n/* c /* n */ */ "
                               "{attribute 'hide'} y := 2;"),
              "(assign (name x) (int 1)) (assign (name y) (int 2))");
}

TEST(Statement, EqualsInsteadOfAssignIsAnError) {
    EXPECT_EQ(statement_error("x = 1;"),
              "this statement does nothing; did you mean ':=' instead of '='?");
}

TEST(Statement, MissingSemicolonIsReportedAfterTheStatement) {
    EXPECT_EQ(statement_error("x := 1\ny := 2;"), "expected ';' after statement");
}

TEST(Statement, ExpressionWithoutEffectIsAnError) {
    EXPECT_EQ(statement_error("x;"), "this statement does nothing; expected an assignment ':=' or "
                                     "a call");
    EXPECT_EQ(statement_error("a + b;"), "this statement does nothing; expected an assignment "
                                         "':=' or a call");
}

TEST(Statement, AssignmentToACallIsAnError) {
    EXPECT_EQ(statement_error("f() := 1;"), "the left side of ':=' must be a variable");
}

TEST(Statement, MissingEndIfIsReported) {
    EXPECT_EQ(statement_error("IF a THEN x := 1;"),
              "expected 'ELSIF', 'ELSE' or 'END_IF', found 'END_PROGRAM'");
}

} // namespace
} // namespace eposp::compiler
