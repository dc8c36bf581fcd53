// What the type checker refuses and warns about, with the message a PLC programmer reads, and
// the run-time errors of generated code naming the POU and the line.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>
#include <ostream>
#include <string>
#include <vector>

namespace eposp::compiler::test {
namespace {

struct Rejected {
    std::string name;
    std::string source;
    std::string message; // a part of the rendered diagnostics
};

class TypeCheck : public testing::TestWithParam<Rejected> {};

TEST_P(TypeCheck, ReportsTheError) {
    const Rejected& c = GetParam();
    StProgram run(c.source);
    EXPECT_FALSE(run.ok());
    EXPECT_NE(run.errors().find(c.message), std::string::npos) << run.errors();
}

std::string main_with(const std::string& declarations, const std::string& body) {
    return "PROGRAM Main\nVAR " + declarations + " END_VAR\n" + body + "\nEND_PROGRAM\n";
}

INSTANTIATE_TEST_SUITE_P(
    Refused, TypeCheck,
    testing::Values(
        Rejected{"NarrowingAssignment", main_with("i : INT; d : DINT;", "i := d;"),
                 "test.st:3:6: error: a DINT value cannot be used as INT (convert it with "
                 "DINT_TO_INT)"},
        Rejected{"RealToInteger", main_with("i : DINT;", "i := 1.5;"),
                 "a LREAL value cannot be used as DINT"},
        Rejected{"SizeofOfAnArrayOfUnknownBounds",
                 "FUNCTION F : DINT\nVAR_IN_OUT a : ARRAY[*] OF INT; END_VAR\nF := SIZEOF(a);\n"
                 "END_FUNCTION\n",
                 "test.st:3:6: error: the size of an ARRAY[*] is known only when running"},
        Rejected{
            "TypedReferenceToAnotherArray",
            main_with("a : ARRAY[0..3] OF INT; p : REF_TO ARRAY[0..9] OF INT;", "p := REF(a);"),
            "a REF_TO ARRAY[0..3] OF INT value cannot be used as REF_TO ARRAY[0..9] OF INT "
            "[E0301]\n"},
        Rejected{"SizeofIsNoSint",
                 main_with("a : ARRAY[0..3] OF INT; s : SINT;", "s := SIZEOF(a);"),
                 "a USINT value cannot be used as SINT (convert it with USINT_TO_SINT)"},
        Rejected{"BoolArithmetic", main_with("b : BOOL; i : INT;", "i := i + b;"),
                 "operands of types INT and BOOL do not match"},
        Rejected{"IfNeedsBool", main_with("i : INT;", "IF i THEN i := 1; END_IF;"),
                 "a INT value cannot be used as BOOL"},
        Rejected{"IfNeedsBoolElement", main_with("a : ARRAY[0..1] OF INT;", "IF a[1] THEN END_IF;"),
                 "a INT value cannot be used as BOOL"},
        Rejected{"AssignToConstant",
                 "PROGRAM Main\nVAR CONSTANT k : INT := 1; END_VAR\nk := 2;\nEND_PROGRAM\n",
                 "cannot be assigned here"},
        Rejected{"PointerMovedByAReal", main_with("p : POINTER TO BYTE;", "p := p + 1.5;"),
                 "a pointer moves by a whole number of bytes, not by a LREAL"},
        Rejected{"AssignToOutputOfInstance",
                 "FUNCTION_BLOCK F\nVAR_OUTPUT q : INT; END_VAR\nq := 1;\nEND_FUNCTION_BLOCK\n" +
                     main_with("f : F;", "f.q := 2;"),
                 "cannot be assigned here"},
        Rejected{"InternalOfInstance",
                 "FUNCTION_BLOCK F\nVAR v : INT; END_VAR\nv := 1;\nEND_FUNCTION_BLOCK\n" +
                     main_with("f : F; i : INT;", "i := f.v;"),
                 "'v' is internal to 'F'"},
        Rejected{"CaseDuplicateLabel",
                 main_with("i : INT;", "CASE i OF 1..5: i := 0; 5: i := 1; END_CASE;"),
                 "overlaps an earlier one"},
        Rejected{"EnumeratorNamedLikeAStandardFunctionIsNoInteger",
                 "TYPE Step : (Idle, Move); END_TYPE\n" + main_with("n : INT;", "n := Move;"),
                 "test.st:4:6: error: a Step value cannot be used as INT"},
        Rejected{"CaseSelectorType", main_with("r : REAL;", "CASE r OF 1: r := 0.0; END_CASE;"),
                 "a CASE selector must be an integer or enumeration"},
        Rejected{"ForVariableAssignedInBody",
                 main_with("i : INT;", "FOR i := 1 TO 3 DO i := 5; END_FOR;"),
                 "control variable of a FOR loop cannot be assigned"},
        Rejected{"ForVariableMustBeInteger", main_with("r : REAL;", "FOR r := 1 TO 3 DO END_FOR;"),
                 "must be a local integer variable"},
        Rejected{"ForStepZero", main_with("i : INT;", "FOR i := 1 TO 3 BY 0 DO END_FOR;"),
                 "BY must not be 0"},
        Rejected{"ExitOutsideLoop", main_with("", "EXIT;"), "EXIT outside a loop"},
        Rejected{"InOutNeedsVariable",
                 "FUNCTION F : INT\nVAR_IN_OUT v : INT; END_VAR\nF := v;\nEND_FUNCTION\n" +
                     main_with("i : INT;", "i := F(v := 3);"),
                 "this expression is not a variable"},
        Rejected{"InOutMustBeConnected",
                 "FUNCTION F : INT\nVAR_IN_OUT v : INT; END_VAR\nF := v;\nEND_FUNCTION\n" +
                     main_with("i : INT;", "i := F();"),
                 "VAR_IN_OUT 'v' of 'F' must be connected"},
        Rejected{"FbInOutMustBeConnectedInEveryCall",
                 "FUNCTION_BLOCK F\nVAR_INPUT a : INT; END_VAR\nVAR_IN_OUT v : INT; END_VAR\n"
                 "v := a;\nEND_FUNCTION_BLOCK\n" +
                     main_with("f : F; i : INT;", "f(a := 1, v := i);\nf(a := 2);"),
                 "VAR_IN_OUT 'v' of 'F' must be connected"},
        Rejected{"TooManyArguments",
                 "FUNCTION F : INT\nVAR_INPUT a : INT; END_VAR\nF := a;\nEND_FUNCTION\n" +
                     main_with("i : INT;", "i := F(1, 2);"),
                 "too many arguments for 'F'"},
        Rejected{"WrongOutput",
                 "FUNCTION_BLOCK F\nVAR_INPUT a : INT; END_VAR\nEND_FUNCTION_BLOCK\n" +
                     main_with("f : F; i : INT;", "f(a => i);"),
                 "'a' is not an output of 'F'"},
        Rejected{"FbCallNeedsFormalArguments",
                 "FUNCTION_BLOCK F\nVAR_INPUT a : INT; END_VAR\nEND_FUNCTION_BLOCK\n" +
                     main_with("f : F;", "f(1);"),
                 "needs formal arguments"},
        Rejected{"CallingAValue", main_with("i : INT;", "i(1);"), "cannot be called"},
        Rejected{"ConstantIndexOutOfBounds", main_with("a : ARRAY[1..3] OF INT;", "a[4] := 1;"),
                 "index 4 is outside"},
        Rejected{"LiteralTooLarge", main_with("s : SINT;", "s := 300;"), "does not fit in SINT"},
        Rejected{"StringToNumber", main_with("i : INT;", "i := 'abc';"),
                 "a STRING[3] value cannot be used as INT"},
        Rejected{"ConcatMixesWstringAndString",
                 main_with("w : WSTRING; s : STRING;", "w := CONCAT(w, s);"),
                 "test.st:3:16: error: CONCAT needs a WSTRING here, not STRING[80]"},
        Rejected{"FindMixesStringAndWstring",
                 main_with("w : WSTRING; s : STRING; i : INT;", "i := FIND(s, w);"),
                 "test.st:3:14: error: FIND needs a STRING here, not WSTRING[80]"},
        Rejected{"LeftOfANumber", main_with("w : WSTRING; i : INT;", "w := LEFT(i, 2);"),
                 "test.st:3:11: error: LEFT needs a STRING or WSTRING here, not INT"},
        Rejected{"WstringFunctionIntoString",
                 main_with("w : WSTRING; s : STRING;", "s := MID(w, 2, 1);"),
                 "test.st:3:6: error: a WSTRING[80] value cannot be used as STRING[80]"},
        Rejected{"WstringComparedWithString",
                 main_with("w : WSTRING; s : STRING; b : BOOL;", "b := w < s;"),
                 "test.st:3:6: error: operands of types WSTRING[80] and STRING[80] do not match"},
        Rejected{"WcharToString", main_with("c : WCHAR; s : STRING;", "s := TO_STRING(c);"),
                 "test.st:3:6: error: WCHAR cannot be converted to STRING[80]"},
        Rejected{"NumberToWstring", main_with("i : INT; w : WSTRING;", "w := INT_TO_WSTRING(i);"),
                 "test.st:3:6: error: INT cannot be converted to WSTRING[80]"},
        Rejected{"WstringToChar", main_with("c : CHAR; w : WSTRING;", "c := WSTRING_TO_CHAR(w);"),
                 "test.st:3:6: error: WSTRING[80] cannot be converted to CHAR"},
        Rejected{"EnNeedsBool", main_with("i : INT;", "i := ADD(EN := i, IN1 := 1, IN2 := 2);"),
                 "test.st:3:16: error: a INT value cannot be used as BOOL"},
        Rejected{"EnIsAnInput", main_with("b : BOOL; i : INT;", "i := ABS(EN => b, IN := i);"),
                 "test.st:3:10: error: EN is an input: write EN := condition"},
        Rejected{"EnoIsAnOutput",
                 main_with("b : BOOL; r : REAL;", "r := INT_TO_REAL(ENO := b, IN := 1);"),
                 "test.st:3:18: error: ENO is an output: write ENO => variable"},
        Rejected{"EnoNeedsBool",
                 main_with("i : INT; s : STRING;", "s := CONCAT(IN1 := s, IN2 := s, ENO => i);"),
                 "test.st:3:40: error: ENO needs a BOOL variable, not INT"},
        Rejected{"EnoToAConstant",
                 "PROGRAM Main\nVAR i : INT; END_VAR\nVAR CONSTANT k : BOOL := TRUE; END_VAR\n"
                 "i := LIMIT(MN := 0, IN := i, MX := 5, ENO => k);\nEND_PROGRAM\n",
                 "test.st:4:46: error: ENO cannot be written to this variable"},
        Rejected{"WrongTypeUnderEn",
                 main_with("b : BOOL; i : INT;", "i := LEFT(EN := b, IN := 'abc', L := 1);"),
                 "test.st:3:6: error: a STRING[3] value cannot be used as INT"},
        Rejected{"StandardFunctionUnknownInput",
                 main_with("i : INT;", "i := LIMIT(MN := 0, IN := i, MAX := 5);"),
                 "test.st:3:30: error: LIMIT has no input 'MAX' here"},
        Rejected{"StandardFunctionInputMissing",
                 main_with("i : INT;", "i := ADD(IN1 := 1, IN3 := 2);"),
                 "test.st:3:20: error: ADD has no input 'IN3' here"},
        Rejected{"StandardFunctionInputTwice",
                 main_with("i : INT;", "i := SUB(IN1 := 1, IN1 := 2);"),
                 "test.st:3:20: error: input 'IN1' of SUB is given twice"},
        Rejected{"StandardFunctionMixedCall", main_with("i : INT;", "i := SUB(IN1 := 1, 2);"),
                 "test.st:3:20: error: a call of SUB names all its inputs or none"},
        Rejected{"EnInAPositionalCall", main_with("b : BOOL; i : INT;", "i := ADD(EN := b, 1, 2);"),
                 "test.st:3:19: error: EN and ENO need a formal call: name every input"},
        Rejected{"Recursion",
                 "FUNCTION F : INT\nVAR_INPUT n : INT; END_VAR\nF := G(n);\nEND_FUNCTION\n"
                 "FUNCTION G : INT\nVAR_INPUT n : INT; END_VAR\nG := F(n - 1);\nEND_FUNCTION\n",
                 "recursion is not allowed"},
        Rejected{"ManyErrorsInOneRun", main_with("i : INT; d : DINT;", "i := d;\ni := 1.5;"),
                 "test.st:4:6"}),
    [](const auto& c) { return c.param.name; });

TEST(Warnings, UnusedUnreachableAndUnassignedResult) {
    const std::string text = diagnostics_of(R"(
FUNCTION F : INT
  VAR_INPUT a : INT; END_VAR
  VAR unused : INT; END_VAR
  RETURN;
  a := a;
END_FUNCTION
)");
    EXPECT_NE(text.find("warning: variable 'unused' is never used"), std::string::npos) << text;
    EXPECT_NE(text.find("warning: this statement is never executed"), std::string::npos) << text;
    EXPECT_NE(text.find("warning: function 'F' never assigns its result"), std::string::npos)
        << text;
}

// IEC 61131-3 forbids it, CODESYS libraries (OSCAT) do it: a warning, and the write works.
TEST(Warnings, WritingAnInputIsAllowedWithAWarning) {
    const std::string source = R"(
FUNCTION BitCount : INT
  VAR_INPUT in : DWORD; END_VAR
  WHILE in > 0 DO
    IF in.0 THEN BitCount := BitCount + 1; END_IF;
    in := SHR(in, 1);
  END_WHILE;
END_FUNCTION
PROGRAM Main
VAR n : INT; END_VAR
n := BitCount(16#F0F0_0001);
END_PROGRAM
)";
    EXPECT_NE(diagnostics_of(source).find("test.st:6:5: warning: 'in' is an input"),
              std::string::npos)
        << diagnostics_of(source);
    StProgram run(source);
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("Main.n"), 9);
}

// An output of a function or FB that nothing in its body writes is a warning; writes through
// `=>`, a bit, REF/ADR or a call that may take it as VAR_IN_OUT count. A program's outputs are
// written from outside too.
TEST(Warnings, AnOutputNeverAssignedIsReported) {
    const std::string text = diagnostics_of(R"(
FUNCTION_BLOCK Probe
  VAR_INPUT a : INT; END_VAR
  VAR_OUTPUT direct, bound, bit, referenced, forgotten : WORD; END_VAR
  VAR edge : R_TRIG; p : REF_TO WORD; END_VAR
  direct := 1;
  edge(CLK := a > 0, Q => bound.0);
  bit.3 := TRUE;
  p := REF(referenced);
END_FUNCTION_BLOCK
PROGRAM Main
  VAR_OUTPUT shown : INT; END_VAR
  VAR probe : Probe; END_VAR
  probe(a := 1);
END_PROGRAM
)");
    EXPECT_NE(text.find("test.st:4:46: warning: output 'forgotten' is never assigned"),
              std::string::npos)
        << text;
    for (const char* name : {"'direct'", "'bound'", "'bit'", "'referenced'", "'shown'"}) {
        EXPECT_EQ(text.find(std::string("output ") + name), std::string::npos) << name << text;
    }
}

// Definite assignment, path by path: a function's result or output that some path to a RETURN
// or to the end leaves unassigned is a warning at its declaration, with a note at each such
// exit. A function's variables start from their initial values at each call, so such a path
// returns those.
struct Paths {
    std::string name;
    std::string source;
    std::vector<std::string> expected; // parts of the diagnostics; empty: no path warning

    friend void PrintTo(const Paths& c, std::ostream* out) { *out << c.source; }
};

class DefiniteAssignment : public testing::TestWithParam<Paths> {};

TEST_P(DefiniteAssignment, WarnsWhereAPathLeavesAnOutputUnassigned) {
    const Paths& c = GetParam();
    const std::string text = diagnostics_of(c.source);
    for (const std::string& part : c.expected) {
        EXPECT_NE(text.find(part), std::string::npos) << part << "\n" << text;
    }
    if (c.expected.empty()) {
        EXPECT_EQ(text.find("may be left unassigned"), std::string::npos) << text;
        EXPECT_EQ(text.find("may return without"), std::string::npos) << text;
    }
}

// `y` is declared at test.st:3:12; the body starts on line 5 and END_FUNCTION follows it.
std::string function_with(const std::string& body, const std::string& outputs = "y : INT;") {
    return "FUNCTION F : INT\nVAR_INPUT c, d : BOOL; n : INT; END_VAR\nVAR_OUTPUT " + outputs +
           " END_VAR\nVAR i : INT; END_VAR\n" + body + "\nEND_FUNCTION\n";
}

const std::string kHelpers = "FUNCTION Fill : BOOL\nVAR_IN_OUT v : INT; END_VAR\nv := 7; Fill := "
                             "TRUE;\nEND_FUNCTION\nFUNCTION Pair : INT\nVAR_OUTPUT q : INT; "
                             "END_VAR\nq := 1; Pair := 2;\nEND_FUNCTION\n";
const std::string kModes = "TYPE Mode : (Idle, Run, Fault); END_TYPE\n";
const std::string kMayBeLeft = "test.st:3:12: warning: output 'y' may be left unassigned (not "
                               "assigned on every path)";

INSTANTIATE_TEST_SUITE_P(
    Paths, DefiniteAssignment,
    testing::Values(
        // Every path assigns: no warning.
        Paths{"AssignedBeforeIf", function_with("y := 0; F := 0;\nIF c THEN y := 1; END_IF"), {}},
        Paths{"EveryBranchAssigns",
              function_with("IF c THEN y := 1; F := 1; ELSIF d THEN y := 2; F := 2;\nELSE y := 3; "
                            "F := 3; END_IF"),
              {}},
        Paths{"NestedIfsAssignOnEveryPath",
              function_with("IF c THEN IF d THEN y := 1; ELSE y := 2; END_IF\nELSE y := 3; "
                            "END_IF F := 1;"),
              {}},
        Paths{"CaseWithElseAssignsInEveryBranch",
              function_with("CASE n OF 1: y := 1; 2, 3: y := 2; ELSE y := 0; END_CASE F := 1;"),
              {}},
        Paths{"CaseOverEveryEnumeratorNeedsNoElse",
              kModes + "FUNCTION F : INT\nVAR_INPUT m : Mode; END_VAR\nCASE m OF Idle: F := 1; "
                       "Run: F := 2;\nFault: F := 3; END_CASE\nEND_FUNCTION\n",
              {}},
        Paths{"CaseOverAWholeSubrangeNeedsNoElse",
              "FUNCTION F : INT\nVAR_INPUT s : INT(0..3); END_VAR\nCASE s OF 0..1: F := 1; 2, "
              "3: F := 2; END_CASE\nEND_FUNCTION\n",
              {}},
        Paths{"ReturnAfterAssignment",
              function_with("IF c THEN y := 1; F := 1; RETURN; END_IF\ny := 2; F := 2;"),
              {}},
        Paths{"RepeatBodyRunsAtLeastOnce",
              function_with("REPEAT i := i + 1; y := i; UNTIL i > n END_REPEAT F := y;"),
              {}},
        Paths{"ExitAfterAssignmentInRepeat",
              function_with("REPEAT y := 1; IF c THEN EXIT; END_IF UNTIL d END_REPEAT F := y;"),
              {}},
        Paths{"EndlessLoopLeftByReturn",
              function_with("WHILE TRUE DO i := i + 1;\nIF i > n THEN y := i; F := i; RETURN; "
                            "END_IF END_WHILE"),
              {}},
        Paths{"OutputBindingAssigns", kHelpers + function_with("F := Pair(q => y);"), {}},
        Paths{"InOutArgumentAssigns", kHelpers + function_with("Fill(y); F := 1;"), {}},
        Paths{"ForControlVariableIsAssignedBeforeTheFirstTest",
              function_with("FOR y := 1 TO n DO i := y; END_FOR F := 1;"),
              {}},
        Paths{"InitialValueCoversTheOtherPaths",
              function_with("IF c THEN y := 1; ok := FALSE; END_IF F := 1; y := 2;",
                            "y : INT; ok : BOOL := TRUE;"),
              {}},
        Paths{"AccumulatorCountsOnTheInitialValue",
              function_with("FOR i := 1 TO n DO F := F + i; END_FOR y := 1;"),
              {}},
        Paths{"PartialWritesAreNotTracked",
              function_with("FOR i := 1 TO 3 DO a[i] := i; END_FOR\nIF c THEN s.0 := TRUE; "
                            "END_IF F := 1;",
                            "a : ARRAY[1..3] OF INT; s : WORD;"),
              {}},
        // An FB's outputs keep their values between calls: a path that leaves one is normal.
        Paths{"FunctionBlockOutputsHoldTheirValue",
              "FUNCTION_BLOCK B\nVAR_INPUT c : BOOL; END_VAR\nVAR_OUTPUT y : INT; END_VAR\nIF c "
              "THEN y := 1; END_IF\nEND_FUNCTION_BLOCK\n",
              {}},
        // Some path leaves it unassigned: a warning, with the exit it reaches.
        Paths{"IfWithoutElse",
              function_with("IF c THEN y := 1; END_IF F := 1;"),
              {kMayBeLeft,
               "test.st:6:1: note: the end of the function is reached without assigning it"}},
        Paths{"ElsifWithoutElse",
              function_with("IF c THEN y := 1; ELSIF d THEN y := 2; END_IF F := 1;"),
              {kMayBeLeft}},
        Paths{"NestedIfMissesIt",
              function_with("IF c THEN IF d THEN y := 1; END_IF\nELSE y := 2; END_IF F := 1;"),
              {kMayBeLeft}},
        Paths{"CaseWithoutElse",
              function_with("CASE n OF 1: y := 1; 2: y := 2; END_CASE F := 1;"),
              {kMayBeLeft}},
        Paths{"CaseOverSomeEnumerators",
              kModes + "FUNCTION F : INT\nVAR_INPUT m : Mode; END_VAR\nCASE m OF Idle: F := 1; "
                       "Run: F := 2; END_CASE\nEND_FUNCTION\n",
              {"test.st:2:10: warning: function 'F' may return without assigning its result "
               "(not assigned on every path)"}},
        Paths{"ResultOnOnePathOnly",
              function_with("y := 1; IF c THEN F := 1; END_IF"),
              {"test.st:1:10: warning: function 'F' may return without assigning its result"}},
        Paths{"ReturnBeforeAssignment",
              function_with("F := 0;\nIF c THEN RETURN; END_IF y := 1;"),
              {kMayBeLeft, "test.st:6:11: note: this RETURN is reached without assigning it"}},
        Paths{"AssignedOnlyInAForLoop",
              function_with("FOR i := 1 TO n DO y := i; END_FOR F := 1;"),
              {kMayBeLeft}},
        Paths{"AssignedOnlyInAWhileLoop",
              function_with("WHILE i < n DO i := i + 1; y := i; END_WHILE F := 1;"),
              {kMayBeLeft}},
        Paths{"ExitBeforeAssignmentInRepeat",
              function_with("REPEAT IF c THEN EXIT; END_IF y := 1; UNTIL d END_REPEAT F := 1;"),
              {kMayBeLeft}},
        Paths{"EnFalseSkipsTheAssignment",
              function_with("y := ABS(EN := c, IN := n); F := 1;"),
              {kMayBeLeft}},
        Paths{"InOutArgumentOnOnePathOnly",
              kHelpers + function_with("IF c THEN Fill(v := y); END_IF F := 1;"),
              {"output 'y' may be left unassigned"}}),
    [](const auto& c) { return c.param.name; });

// An output or result that nothing assigns gets the "never assigned" warning only.
TEST(Warnings, NeverAssignedIsNotReportedTwice) {
    const std::string text = diagnostics_of(function_with("i := 1;"));
    EXPECT_NE(text.find("warning: output 'y' is never assigned"), std::string::npos) << text;
    EXPECT_NE(text.find("warning: function 'F' never assigns its result"), std::string::npos)
        << text;
    EXPECT_EQ(text.find("may be left unassigned"), std::string::npos) << text;
    EXPECT_EQ(text.find("may return without"), std::string::npos) << text;
}

// A declaration that failed is reported once, not again at every use of the variable.
TEST(Diagnostics, AFailedDeclarationIsReportedOnce) {
    const std::string text = diagnostics_of("PROGRAM Main\nVAR n : INT := 3; a : ARRAY[1..n] OF "
                                            "INT; END_VAR\na[1] := 2;\nEND_PROGRAM\n");
    EXPECT_NE(text.find("test.st:2:29: error: array bounds must be constants"), std::string::npos)
        << text;
    EXPECT_EQ(text.find("'a' is not a variable"), std::string::npos) << text;
}

TEST(RunTimeErrors, DivisionByZeroNamesThePouAndLine) {
    StProgram run(R"(
FUNCTION Ratio : DINT
  VAR_INPUT a, b : DINT; END_VAR
  Ratio := a / b;
END_FUNCTION
PROGRAM Main
VAR r, zero : DINT; END_VAR
r := Ratio(10, zero);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "division by zero in Ratio at line 4");
}

TEST(RunTimeErrors, IndexOutOfRange) {
    StProgram run(R"(
PROGRAM Main
VAR a : ARRAY[1..3] OF INT; i : INT := 4; END_VAR
a[i] := 1;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "array index out of range in Main at line 4");
}

struct IndexTrap {
    std::string name;
    std::string declarations;
    std::string access;
};

class IndexOutOfRange : public testing::TestWithParam<IndexTrap> {};

// Each index form the code generator has its own path for stops at the bound it crosses.
TEST_P(IndexOutOfRange, StopsTheTask) {
    StProgram run("PROGRAM Main\nVAR a : ARRAY[1..3] OF DINT; x : DINT; " +
                  GetParam().declarations + " END_VAR\nx := " + GetParam().access +
                  ";\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "array index out of range in Main at line 3");
}

INSTANTIATE_TEST_SUITE_P(
    Forms, IndexOutOfRange,
    testing::Values(IndexTrap{"DintAbove", "j : DINT := 4;", "a[j]"},
                    IndexTrap{"DintBelow", "j : DINT := 0;", "a[j]"},
                    IndexTrap{"IntBelow", "i : INT := -1;", "a[i]"},
                    IndexTrap{"UdintHuge", "u : UDINT := 16#80000001;", "a[u]"},
                    IndexTrap{"PlusConstantAbove", "j : DINT := 3;", "a[j + 1]"},
                    IndexTrap{"MinusConstantBelow", "j : DINT := 1;", "a[j - 1]"},
                    IndexTrap{"SumWrapsAround", "j : DINT := 2147483647;", "a[j + 2]"}),
    [](const auto& param_info) { return param_info.param.name; });

// Each index of a multi-dimensional array is checked against its own dimension, even where
// the position it gives overall would be inside the array.
TEST(RunTimeErrors, EveryIndexOfAMatrixIsChecked) {
    StProgram run(R"(
PROGRAM Main
VAR m : ARRAY[0..2, 1..3] OF INT; i : INT := 0; j : INT := 4; x : INT; END_VAR
m[2, 3] := 7;
x := m[i, j];
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "array index out of range in Main at line 5");
}

TEST(Robustness, GarbageNeverCrashes) {
    for (const char* source :
         {"PROGRAM Main VAR x : INT; END_VAR x := x. ; END_PROGRAM",
          "FUNCTION F : INT END_FUNCTION",
          "PROGRAM Main VAR a : ARRAY[1..0] OF INT; END_VAR END_PROGRAM",
          "TYPE T : STRUCT a : T; END_STRUCT; END_TYPE PROGRAM Main VAR t : T; END_VAR END_PROGRAM",
          "PROGRAM Main VAR s : STRING[0]; END_VAR END_PROGRAM",
          "PROGRAM Main VAR x : INT; END_VAR x := UNKNOWN(1) + y; END_PROGRAM"}) {
        StProgram run(source);
        EXPECT_FALSE(run.errors().empty()) << source;
    }
}

} // namespace
} // namespace eposp::compiler::test
