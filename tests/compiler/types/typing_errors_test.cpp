// The typing stage reports every name and type error itself (issue 17), with the codes that code
// generation reported before: each case is typed without code generation (types::analyse) and
// must give exactly its codes; the accepted programs must type without any.
#include "typing_helpers.hpp"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::compiler::test {
namespace {

using Case = TypingCase;

std::string main_with(const std::string& declarations, const std::string& body) {
    return "PROGRAM Main\nVAR " + declarations + " END_VAR\n" + body + "\nEND_PROGRAM\n";
}

/// A configuration running `Main` (a count, an output) as Inst0 and `Consumer` as declared by
/// `consumer`, with the access paths `access`.
std::string cell_with(const std::string& consumer, const std::string& access = "") {
    return "PROGRAM Main\nVAR count : INT; END_VAR\nVAR_OUTPUT out : DINT; END_VAR\n"
           "END_PROGRAM\n"
           "PROGRAM Consumer\nVAR_INPUT n : DINT; small : SINT; END_VAR\n"
           "VAR_OUTPUT twice : DINT; END_VAR\nEND_PROGRAM\n"
           "CONFIGURATION Cell\nVAR_GLOBAL total : DINT; small : INT; END_VAR\n" +
           (access.empty() ? "" : "VAR_ACCESS " + access + " END_VAR\n") +
           "RESOURCE Res0 ON PLC\nTASK Fast(INTERVAL := T#1ms, PRIORITY := 0);\n"
           "PROGRAM Inst0 WITH Fast : Main;\nPROGRAM C1 WITH Fast : Consumer" +
           consumer + ";\nEND_RESOURCE\nEND_CONFIGURATION\n";
}

class TypingErrors : public testing::TestWithParam<Case> {};

TEST_P(TypingErrors, AreReportedByTheTypingStage) {
    const Case& c = GetParam();
    const auto t = type_source(c.source);
    EXPECT_EQ(codes_of(t->diagnostics), c.codes) << t->errors();
}

const char* const kCounter = "FUNCTION_BLOCK Counter\nVAR_INPUT up : BOOL; END_VAR\n"
                             "VAR n : INT; END_VAR\nVAR_OUTPUT q : INT; END_VAR\n"
                             "n := n + 1;\nEND_FUNCTION_BLOCK\n";

INSTANTIATE_TEST_SUITE_P(
    Refused, TypingErrors,
    testing::Values(
        Case{"LiteralTooLarge", main_with("s : SINT;", "s := 300;"), {"E0311"}},
        Case{"WcharToString",
             main_with("c : WCHAR; s : STRING;", "s := WCHAR_TO_STRING(c);"),
             {"E0310"}},
        Case{"NumberToWstring",
             main_with("i : INT; w : WSTRING;", "w := INT_TO_WSTRING(i);"),
             {"E0310"}},
        Case{"WstringToTime",
             main_with("w : WSTRING; t : TIME;", "t := WSTRING_TO_TIME(w);"),
             {"E0310"}},
        Case{"ConcatMixesWstringAndString",
             main_with("w : WSTRING; s : STRING;", "w := CONCAT(w, s);"),
             {"E0305"}},
        Case{"FindMixesStringAndWstring",
             main_with("w : WSTRING; s : STRING; i : INT;", "i := FIND(s, w);"),
             {"E0305"}},
        Case{"CaseSelectorType",
             main_with("r : REAL; i : INT;", "CASE r OF 1: i := 1; END_CASE;"),
             {"E0304"}},
        Case{"PointerMovedByAReal", main_with("p : POINTER TO BYTE;", "p := p + 1.5;"), {"E0304"}},
        Case{"ModuloOfReals", main_with("r : REAL;", "r := r MOD 2.0;"), {"E0304"}},
        Case{"DateMovedByATime", main_with("d : DATE;", "d := d + T#1s;"), {"E0303"}},
        Case{"IntPlusUdintHaveNoCommonType",
             main_with("i : INT; u : UDINT; d : DINT;", "d := i + u;"),
             {"E0303"}},
        Case{"EnoNeedsBool",
             main_with("i : INT; x : INT;", "x := ADD(IN1 := 1, IN2 := 2, ENO => i);"),
             {"E0301"}},
        Case{"TooManyArguments",
             "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nF := a;\nEND_FUNCTION\n" +
                 main_with("i : INT;", "i := F(1, 2);"),
             {"E0306"}},
        Case{"WrongOutput",
             "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nF := a;\nEND_FUNCTION\n" +
                 main_with("i : INT;", "i := F(a => i);"),
             {"E0210"}},
        Case{"InOutNeedsVariable",
             "FUNCTION F : INT\nVAR_IN_OUT a : INT; END_VAR\nF := a;\nEND_FUNCTION\n" +
                 main_with("i : INT;", "i := F(a := 3);"),
             {"E0315"}},
        Case{"BitOfAnOutputTarget",
             std::string(kCounter) + main_with("c : Counter; w : WORD;", "c(q => w.0);"),
             {"E0315"}},
        Case{"StandardFunctionUnknownInput",
             main_with("i : INT;", "i := LIMIT(MN := 1, IN := 2, MAX := 3);"),
             {"E0210"}},
        Case{"StandardFunctionInputMissing",
             main_with("i : INT;", "i := ADD(IN1 := 1, IN3 := 2);"),
             {"E0210"}},
        Case{"InternalOfInstance",
             std::string(kCounter) + main_with("c : Counter; i : INT;", "i := c.n;"),
             {"E0212"}},
        Case{"CallOfAnFbType",
             std::string(kCounter) + main_with("i : INT;", "Counter(up := TRUE);"),
             {"E0204"}},
        Case{"CallOfAValue", main_with("i : INT;", "i();"), {"E0204"}},
        Case{"FbCallHasNoValue",
             std::string(kCounter) + main_with("c : Counter; i : INT;", "i := c(up := TRUE);"),
             {"E0309"}},
        Case{"TooFewIndices",
             main_with("a : ARRAY[1..3, 1..3] OF INT; i : INT;", "i := a[1];"),
             {"E0308"}},
        Case{"EnumValueAsTarget",
             "TYPE State : (Idle, Run); END_TYPE\n" + main_with("s : State;", "State.Run := s;"),
             {"E0204"}},
        Case{"UpperBoundOfANonArray",
             main_with("i : INT; d : DINT;", "d := UPPER_BOUND(i, 1);"),
             {"E0305"}},
        Case{"DimensionTooLarge",
             main_with("a : ARRAY[1..3] OF INT; d : DINT;", "d := UPPER_BOUND(a, 2);"),
             {"E0313"}},
        Case{"AnyTakesNoArray",
             "FUNCTION Show : INT\nVAR_INPUT v : ANY; END_VAR\nEND_FUNCTION\n" +
                 main_with("a : ARRAY[1..2] OF INT; i : INT;", "i := Show(a);"),
             {"E0305"}},
        // A value of another type is E0301 as an initial value too (was E0313, issue 17).
        Case{"RealInitialValueOfAnInteger",
             "TYPE S : STRUCT m : INT := 1.5; END_STRUCT END_TYPE\n",
             {"E0301"}},
        Case{"SubrangeOfAReal", "TYPE T : REAL(1..5); END_TYPE\n", {"E0312"}},
        Case{"EmptySubrange", "TYPE T : INT(5..1); END_TYPE\n", {"E0314"}},
        Case{"ConstantDefinedThroughItself",
             "VAR_GLOBAL CONSTANT a : INT := b; END_VAR\nVAR_GLOBAL CONSTANT b : INT := a; "
             "END_VAR\n",
             {"E0313", "E0313"}},
        Case{"ConnectionNarrowingInput", cell_with(" (small := small)"), {"E0301"}},
        Case{"ConnectionNarrowingOutput", cell_with(" (twice => small)"), {"E0301"}},
        Case{"ConnectionToNoInput", cell_with(" (twice := total)"), {"E0210"}},
        Case{"AccessPathToNoVariable", cell_with("", "a : Inst0.nothing : INT;"), {"E0201"}},
        Case{"AccessPathOfAnotherType", cell_with("", "a : Inst0.count : DINT;"), {"E0301"}},
        Case{"AccessPathNamedTwice",
             cell_with("", "a : Inst0.count : INT; a : total : DINT;"),
             {"E0202"}},
        Case{"AccessPathNamedLikeAGlobal", cell_with("", "total : Inst0.count : INT;"), {"E0202"}},
        // Initial values are folded as code generation writes them (types/initial_constant.cpp).
        Case{"ArrayInitialValueOfAScalar", main_with("i : INT := [1, 2];", "i := 1;"), {"E0301"}},
        Case{"FoldedInitialValueTooLarge",
             main_with("x : SINT := 100 + 100;", "x := 1;"),
             {"E0311"}},
        // A duration times a REAL and a TIME_OF_DAY sum are constants since they are folded by
        // the VM's own functions (constant_time_operations.cpp); a NaN and a division by zero
        // are left to run time.
        Case{"NanIsNoConstant", main_with("r : LREAL := SQRT(-1.0);", "r := r;"), {"E0313"}},
        Case{"DurationDividedByZeroIsNoConstant",
             main_with("t : TIME := T#1s / 0.0;", "t := t;"),
             {"E0313"}},
        // What only code generation refused before (eposp check passed, eposp build failed).
        Case{"BitBeyondTheWord", main_with("w : WORD; b : BOOL;", "b := w.16;"), {"E0105"}},
        Case{"BitOfABool", main_with("a, b : BOOL;", "b := a.0;"), {"E0304"}},
        Case{"DereferenceOfAnInteger", main_with("x : INT;", "x := x^;"), {"E0304"}},
        Case{"StructuresCompared",
             "TYPE S : STRUCT a : INT; END_STRUCT; END_TYPE\n" +
                 main_with("s, t : S; b : BOOL;", "b := s = t;"),
             {"E0304"}},
        Case{"CaseLabelOfAVariable",
             main_with("x, y : INT;", "CASE x OF y: x := 1; END_CASE;"),
             {"E0313"}},
        Case{"RepetitionBeyondLint",
             main_with("a : ARRAY[1..2] OF LINT := [10000000000000000000(0)];", "a[1] := 1;"),
             {"E0313"}}));

class TypingAccepts : public testing::TestWithParam<Case> {};

TEST_P(TypingAccepts, WithoutErrors) {
    const Case& c = GetParam();
    const auto t = type_source(c.source);
    EXPECT_TRUE(t->diagnostics.all().empty()) << t->errors();
}

INSTANTIATE_TEST_SUITE_P(
    Accepted, TypingAccepts,
    testing::Values(
        Case{"PointerArithmetic",
             main_with("p : POINTER TO INT; k : DINT; l : LINT;",
                       "p := p + 2; p := p + k; p := p - l;"),
             {}},
        Case{"TimeOfDayPlusTime",
             main_with("t : TOD; d : DT; x : TIME;", "t := t + T#2h; d := d - T#1s; x := d - d;"),
             {}},
        Case{"AnyTakesElementaryValuesAndStrings",
             "FUNCTION Show : INT\nVAR_INPUT v : ANY; END_VAR\nEND_FUNCTION\n" +
                 main_with("i : INT; s : STRING; r : LREAL;",
                           "i := Show(i); i := Show(s); i := Show(r); i := Show(T#1s);"),
             {}},
        Case{"FbReferringToItsOwnType",
             "FUNCTION_BLOCK Link\nVAR_INPUT next : REF_TO Link; END_VAR\n"
             "VAR_OUTPUT depth : INT; END_VAR\n"
             "IF next <> NULL THEN depth := next^.depth + 1; END_IF;\nEND_FUNCTION_BLOCK\n" +
                 main_with("a, b : Link;", "b();\na(next := REF(b));"),
             {}},
        Case{"EnumValueAsSubrangeBoundAndInitialValue",
             "TYPE State : (Idle, Run, Fault); END_TYPE\n" +
                 main_with("w : INT(State.Idle..State.Run) := State.Run;", "w := 1;"),
             {}},
        Case{"ConnectionsToOtherProgramsAndGlobals",
             cell_with(" (n := Inst0.out, twice => total)", "c : Res0.Inst0.count : INT;"),
             {}},
        Case{"IntegersMasked",
             main_with("a : SINT; b : INT; x : INT;", "IF (a AND b) <> 0 THEN x := 1; END_IF;"),
             {}}));

} // namespace
} // namespace eposp::compiler::test
