// The rules of the standard functions' manifest rows (vm/stdlib/manifest.hpp) are the typing
// stage's: formal input names, the number of inputs and the ANY_* family of each input are
// reported without code generation (types::analyse), which only meets programs that keep them.
#include "typing_helpers.hpp"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::compiler::test {
namespace {

using Case = TypingCase;

const char* const kDeclarations = "n : DINT; w : WORD; x : BOOL; r : REAL; s : STRING; "
                                  "ws : WSTRING; arr : ARRAY[1..3] OF INT; p : POINTER TO INT; "
                                  "st : TON; tm : TIME; tod : TOD;";

class StandardFunctionErrors : public testing::TestWithParam<Case> {};

TEST_P(StandardFunctionErrors, AreReportedByTheTypingStage) {
    const Case& c = GetParam();
    const auto t = type_body(kDeclarations, c.source);
    EXPECT_EQ(codes_of(t->diagnostics), c.codes) << t->errors();
}

INSTANTIATE_TEST_SUITE_P(
    Manifest, StandardFunctionErrors,
    testing::Values(
        // Formal inputs: the names of the row, numbered ones from IN1 (MUX: K, IN0, ...).
        Case{"NumberedInputsStartAtIn1", "n := ADD(IN := 1, IN2 := 2);", {"E0210"}},
        Case{"OneInputIsIn", "n := ABS(IN1 := n);", {"E0210"}},
        Case{"TextInputIsIn", "n := LEN(IN1 := s);", {"E0210"}},
        Case{"SelHasNoIn2", "n := SEL(G := x, IN0 := 1, IN1 := 2, IN2 := 3);", {"E0210"}},
        Case{"BoundsArePositional", "n := LOWER_BOUND(ARR := arr, DIM := 1);", {"E0210"}},
        Case{"NoOutputs", "n := ADD(IN1 => n, IN2 := 1);", {"E0210"}},
        // The number of inputs.
        Case{"ConcatTakesTwoTexts", "s := CONCAT(s);", {"E0306"}},
        Case{"MuxTakesTwoValues", "n := MUX(1, n);", {"E0306"}},
        Case{"SubTakesTwo", "n := SUB(1, 2, 3);", {"E0306"}},
        // The family's input types.
        Case{"AndNeedsBitStrings", "n := AND(n, n);", {"E0304"}},
        Case{"NotNeedsBitStringsOrIntegers", "r := NOT(r);", {"E0304"}},
        Case{"ExptRaisesToANumber", "r := EXPT(2.0, s);", {"E0305"}},
        Case{"LengthsAreIntegers", "s := LEFT(s, r);", {"E0305"}},
        Case{"TextsAreOfOneWidth", "s := INSERT(s, ws, 1);", {"E0305"}},
        Case{"MaxOfElementaryValues", "p := MAX(p, p);", {"E0305"}},
        Case{"LimitOfElementaryValues", "arr := LIMIT(arr, arr, arr);", {"E0305"}},
        Case{"ShiftsABitString", "r := SHL(r, 1);", {"E0305"}},
        Case{"ShiftCountIsAnInteger", "w := SHL(w, r);", {"E0305"}},
        Case{"TimeScalesByANumber", "n := TIME_TO_DINT(MUL_TIME(T#1s, s));", {"E0305"}},
        // ADD and MUL on times extend step by step through table 30's rows (table 24).
        Case{"AddStepOnTwoTimesOfDay", "tod := ADD(tod, tod, tm);", {"E0305"}},
        Case{"AddStepOnADurationAndATimeOfDay", "tm := ADD(tm, tm, tod);", {"E0305"}},
        Case{"MulStepByATime", "tm := MUL(tm, 2, tm);", {"E0305"}},
        Case{"SubOnTimesTakesTwo", "tm := SUB(tm, tm, tm);", {"E0306"}},
        Case{"NamedTimeFunctionsTakeTwo", "tm := ADD_TIME(tm, tm, tm);", {"E0306"}},
        // What the rows accept.
        Case{"FormalInputsInAnyOrder",
             "n := LIMIT(MX := 9, IN := n, MN := 0); n := MUX(K := 0, IN0 := 1, IN1 := 2); "
             "n := ADD(IN2 := 1, IN1 := 2); w := SHL(N := 1, IN := w); "
             "s := INSERT(IN2 := s, P := 1, IN1 := s); n := NOT(n);",
             {}}));

} // namespace
} // namespace eposp::compiler::test
