// An initial value is a constant expression of the variable's type (IEC 61131-3 ed. 3, 6.5.1.3):
// named CONSTANTs of every type and durations scaled by integers fold when compiling, to the
// value the same expression has at run time. Typing accepted them and code generation refused
// them (E0313: `eposp check` passed, `eposp build` failed).
#include "codegen_harness.hpp"

#include <cstdint>
#include <gtest/gtest.h>
#include <string>

namespace eposp::compiler::test {
namespace {

TEST(ConstantInitialValues, FoldToTheValueTheExpressionHasAtRunTime) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kPeriod : TIME := T#1ms * 4;
    kStart : TIME := T#1s;
    kRatio : REAL := 1.5;
    kQuarter : INT := 7 / 2;
    kOn : BOOL := TRUE;
    kName : STRING := 'ab';
END_VAR
VAR
    period : TIME := kPeriod; period_now : TIME;
    half : TIME := kStart / 2 - T#100ms; half_now : TIME;
    back : TIME := -kPeriod / -1; back_now : TIME;
    start : DT := DT#2020-01-01-00:00:00 + T#1h; start_now : DT;
    ratio : LREAL := kRatio * 2.0;
    quarter : REAL := kQuarter;
    lit : BOOL := kOn;
    name : STRING := kName;
END_VAR
period_now := T#1ms * 4;
half_now := kStart / 2 - T#100ms;
back_now := -kPeriod / -1;
start_now := DT#2020-01-01-00:00:00 + T#1h;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    const auto period = run.get<std::int64_t>("Main.period");
    const auto half = run.get<std::int64_t>("Main.half");
    const auto back = run.get<std::int64_t>("Main.back");
    const auto start = run.get<std::int64_t>("Main.start");
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(period, 4'000'000);
    EXPECT_EQ(period, run.get<std::int64_t>("Main.period_now"));
    EXPECT_EQ(half, 400'000'000);
    EXPECT_EQ(half, run.get<std::int64_t>("Main.half_now"));
    EXPECT_EQ(back, 4'000'000);
    EXPECT_EQ(back, run.get<std::int64_t>("Main.back_now"));
    EXPECT_EQ(start, run.get<std::int64_t>("Main.start_now"));
    EXPECT_EQ(run.get<double>("Main.ratio"), 3.0);
    EXPECT_EQ(run.get<float>("Main.quarter"), 3.0F); // the INT constant's value, not 3.5
    EXPECT_TRUE(run.get<bool>("Main.lit"));
    EXPECT_EQ(run.get_string("Main.name"), "ab");
}

// A REAL folds in single precision at every step, as it computes at run time; an LREAL in double.
// `kTenth * 3.0` is a REAL product (the literal takes kTenth's type) also inside an LREAL, as
// `tenth * 3.0` computes at run time (MulF32, then widened); the initial-value folder computed
// it in the variable's double precision, and this test compared it with another expression,
// REAL_TO_LREAL(tenth) * 3.0 (issue 17). With an LREAL operand the product is an LREAL one.
TEST(ConstantInitialValues, RealsRoundAtEveryStepAsAtRunTime) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kSum : REAL := 16777216.0 + 1.0 + 1.0;
    kTenth : REAL := 0.1;
    kWide : LREAL := kTenth * 3.0;
    kThree : LREAL := 3.0;
    kWider : LREAL := kTenth * kThree;
    kLongSum : LREAL := 9007199254740992.0 + 1.0 + 1.0;
END_VAR
VAR
    sum : REAL := kSum; sum_now : REAL;
    wide : LREAL := kWide; wide_now : LREAL; tenth : REAL := 0.1;
    wider : LREAL := kWider; wider_now : LREAL; three : LREAL := 3.0;
    long_sum : LREAL := kLongSum; long_sum_now : LREAL;
END_VAR
sum_now := 16777216.0 + 1.0 + 1.0;
wide_now := tenth * 3.0;
wider_now := tenth * three;
long_sum_now := 9007199254740992.0 + 1.0 + 1.0;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<float>("Main.sum"), 16777216.0F);
    EXPECT_EQ(run.get<float>("Main.sum"), run.get<float>("Main.sum_now"));
    EXPECT_EQ(run.get<double>("Main.wide"), static_cast<double>(0.1F * 3.0F));
    EXPECT_EQ(run.get<double>("Main.wide"), run.get<double>("Main.wide_now"));
    EXPECT_EQ(run.get<double>("Main.wider"), static_cast<double>(0.1F) * 3.0);
    EXPECT_EQ(run.get<double>("Main.wider"), run.get<double>("Main.wider_now"));
    EXPECT_EQ(run.get<double>("Main.long_sum"), run.get<double>("Main.long_sum_now"));
}

// ULINT and LWORD constants fold modulo 2^64: one named by another above LINT's range too.
TEST(ConstantInitialValues, UnsignedSixtyFourBitConstantsFoldAboveLintsRange) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kMask : LWORD := LWORD#16#FFFFFFFFFFFFFFF0;
    kSame : LWORD := kMask;
    kTop : ULINT := 18446744073709551615;
    kHalf : ULINT := kTop / 2;
END_VAR
VAR
    same : LWORD := kSame;
    half : ULINT := kHalf; half_now : ULINT; top : ULINT := kTop;
END_VAR
half_now := top / 2;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::uint64_t>("Main.same"), 0xFFFF'FFFF'FFFF'FFF0ULL);
    EXPECT_EQ(run.get<std::uint64_t>("Main.half"), 0x7FFF'FFFF'FFFF'FFFFULL);
    EXPECT_EQ(run.get<std::uint64_t>("Main.half"), run.get<std::uint64_t>("Main.half_now"));
}

// A constant whose value is out of its type's range is refused in DINT and UDINT as in SINT
// and INT (E0311, issue 17): they wrapped silently at 32 bits before, as the same expression
// wraps at run time; so is a DINT sum stored into a LINT, which wraps in DINT at run time too.
// A DINT constant in a LINT expression still has its own type's value.
TEST(ConstantInitialValues, IntegersOutOfTheirTypesRangeAreRefused) {
    const std::string errors = diagnostics_of(R"(PROGRAM Main
VAR CONSTANT
    kHalf : DINT := (2147483647 + 1) / 2;
    kWrapped : DINT := 2147483647 + 1;
    kUnsigned : UDINT := (UDINT#4294967295 + 1) / 2;
    kMin : DINT := -2147483647 - 1;
END_VAR
VAR
    half : DINT := kHalf; unsigned_half : UDINT := kUnsigned; wrapped : DINT := kMin / -1;
    sum : LINT := kMin - 1;
END_VAR
half := 1;
END_PROGRAM
)");
    std::size_t refused = 0;
    for (auto at = errors.find("E0311"); at != std::string::npos;
         at = errors.find("E0311", at + 1)) {
        ++refused;
    }
    EXPECT_EQ(refused, 5U) << errors;
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kTop : DINT := 2147483647;
    kWide : LINT := kTop + LINT#1;
END_VAR
VAR
    big : DINT := 2147483647;
    wide : LINT := kWide; wide_now : LINT;
END_VAR
wide_now := DINT_TO_LINT(big) + 1;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int64_t>("Main.wide"), 2'147'483'648);
    EXPECT_EQ(run.get<std::int64_t>("Main.wide"), run.get<std::int64_t>("Main.wide_now"));
}

// NOT, AND, OR and XOR fold as they compute at run time: NOT flips the bits of its operand's
// type (a BYTE's eight, a UINT's sixteen), a BOOL expression gives TRUE or FALSE. They gave
// E0313 ("the initial value must be a constant") before.
TEST(ConstantInitialValues, LogicOperatorsFoldAsAtRunTime) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kLow : BYTE := 16#0F;
    kOn : BOOL := TRUE;
    kCount : UINT := 3;
END_VAR
VAR
    low : BYTE := 16#0F; count : UINT := 3; five : INT := 5; on : BOOL := TRUE;
    flipped : BYTE := NOT 16#0F; flipped_now : BYTE;
    named : BYTE := NOT kLow; named_now : BYTE;
    mixed : BYTE := kLow OR 16#30; mixed_now : BYTE;
    masked : DWORD := 16#FF00 AND 16#0FF0; masked_now : DWORD;
    toggled : WORD := 16#F0F0 XOR 16#FFFF; toggled_now : WORD;
    negative : INT := NOT 5; negative_now : INT;
    sixteen : UINT := NOT kCount; sixteen_now : UINT;
    off : BOOL := NOT kOn; off_now : BOOL;
    both : BOOL := kOn AND NOT FALSE; both_now : BOOL;
    either : BOOL := FALSE XOR kOn OR FALSE; either_now : BOOL;
END_VAR
flipped_now := NOT low;
named_now := NOT low;
mixed_now := low OR 16#30;
masked_now := DWORD#16#FF00 AND 16#0FF0;
toggled_now := WORD#16#F0F0 XOR 16#FFFF;
negative_now := NOT five;
sixteen_now := NOT count;
off_now := NOT on;
both_now := on AND NOT FALSE;
either_now := FALSE XOR on OR FALSE;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::uint8_t>("Main.flipped"), 0xF0);
    EXPECT_EQ(run.get<std::uint8_t>("Main.named"), 0xF0);
    EXPECT_EQ(run.get<std::uint8_t>("Main.mixed"), 0x3F);
    EXPECT_EQ(run.get<std::uint32_t>("Main.masked"), 0x0F00U);
    EXPECT_EQ(run.get<std::uint16_t>("Main.toggled"), 0x0F0F);
    EXPECT_EQ(run.get<std::int16_t>("Main.negative"), -6);
    EXPECT_EQ(run.get<std::uint16_t>("Main.sixteen"), 0xFFFC);
    EXPECT_FALSE(run.get<bool>("Main.off"));
    EXPECT_TRUE(run.get<bool>("Main.both"));
    EXPECT_TRUE(run.get<bool>("Main.either"));
    for (const char* name : {"flipped", "named", "mixed"}) {
        EXPECT_EQ(run.get<std::uint8_t>(std::string("Main.") + name),
                  run.get<std::uint8_t>(std::string("Main.") + name + "_now"))
            << name;
    }
    EXPECT_EQ(run.get<std::uint32_t>("Main.masked"), run.get<std::uint32_t>("Main.masked_now"));
    EXPECT_EQ(run.get<std::uint16_t>("Main.toggled"), run.get<std::uint16_t>("Main.toggled_now"));
    EXPECT_EQ(run.get<std::int16_t>("Main.negative"), run.get<std::int16_t>("Main.negative_now"));
    EXPECT_EQ(run.get<std::uint16_t>("Main.sixteen"), run.get<std::uint16_t>("Main.sixteen_now"));
    for (const char* name : {"off", "both", "either"}) {
        EXPECT_EQ(run.get<bool>(std::string("Main.") + name),
                  run.get<bool>(std::string("Main.") + name + "_now"))
            << name;
    }
}

// Division by -1 folds as it computes at run time: MIN / -1 is out of its type's range (E0311,
// in DINT above, in LINT in diagnostics/types_initial_value_ranges.st), MOD -1 is 0 (also of MIN), in array bounds, CONSTANTs and initial
// values alike. The type table's folder refused
// both as no constant: "array bounds must be constants", E0313 on the initial values (issue 17).
TEST(ConstantInitialValues, DivisionByMinusOneFoldsAsAtRunTime) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kMin : DINT := -2147483647 - 1;
    kNone : DINT := 7 MOD -1;
    kLongMin : LINT := -9223372036854775807 - 1;
END_VAR
VAR
    min : DINT := -2147483647 - 1; long_min : LINT := -9223372036854775807 - 1; minus : DINT := -1;
    long_minus : LINT := -1;
    table : ARRAY[0..5 MOD -1] OF INT;
    none : DINT := kNone; none_now : DINT;
    rest : DINT := kMin MOD -1; rest_now : DINT;
    long_rest : LINT := kLongMin MOD -1; long_rest_now : LINT;
END_VAR
none_now := 7 MOD minus;
rest_now := min MOD minus;
long_rest_now := long_min MOD long_minus;
table[0] := 1;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.none"), 0);
    EXPECT_EQ(run.get<std::int32_t>("Main.rest"), 0);
    EXPECT_EQ(run.get<std::int64_t>("Main.long_rest"), 0);
    for (const char* name : {"none", "rest"}) {
        EXPECT_EQ(run.get<std::int32_t>(std::string("Main.") + name),
                  run.get<std::int32_t>(std::string("Main.") + name + "_now"))
            << name;
    }
    for (const char* name : {"long_rest"}) {
        EXPECT_EQ(run.get<std::int64_t>(std::string("Main.") + name),
                  run.get<std::int64_t>(std::string("Main.") + name + "_now"))
            << name;
    }
}

// A part of a REAL initial value typed as an integer computes as that integer, then converts:
// `kSeven / 2` is INT division, 3.0 as at run time. The initial-value folder computed every part
// in reals and gave 3.5 (issue 17).
TEST(ConstantInitialValues, IntegerPartsOfARealComputeAsIntegers) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kSeven : INT := 7;
    kBig : INT := 20000;
END_VAR
VAR
    seven : INT := 7; big : INT := 20000;
    half : REAL := kSeven / 2; half_now : REAL;
    wide : LREAL := DINT#7 / 2; wide_now : LREAL;
    mixed : LREAL := kSeven / 2 + 0.5; mixed_now : LREAL;
    wrapped : REAL := kBig * 2; wrapped_now : REAL;
END_VAR
half_now := seven / 2;
wide_now := DINT#7 / 2;
mixed_now := seven / 2 + 0.5;
wrapped_now := big * 2;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<float>("Main.half"), 3.0F);
    EXPECT_EQ(run.get<float>("Main.half"), run.get<float>("Main.half_now"));
    EXPECT_EQ(run.get<double>("Main.wide"), 3.0);
    EXPECT_EQ(run.get<double>("Main.wide"), run.get<double>("Main.wide_now"));
    EXPECT_EQ(run.get<double>("Main.mixed"), 3.5);
    EXPECT_EQ(run.get<double>("Main.mixed"), run.get<double>("Main.mixed_now"));
    EXPECT_EQ(run.get<float>("Main.wrapped"), run.get<float>("Main.wrapped_now"));
}

// NOT of a constant of a narrower type in a wider variable flips the narrower type's bits at
// run time (NOT kLow is 16#F0 in a DWORD too); its initial value is that value, the typing
// stage's constant of the expression (it was refused as no constant before, E0313).
TEST(ConstantInitialValues, NotOfANarrowerConstantFlipsItsOwnBits) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kLow : BYTE := 16#0F;
END_VAR
VAR
    wide : DWORD := NOT kLow; wide_now : DWORD;
END_VAR
wide_now := NOT kLow;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::uint32_t>("Main.wide"), 0xF0U);
    EXPECT_EQ(run.get<std::uint32_t>("Main.wide"), run.get<std::uint32_t>("Main.wide_now"));
}

// The pure standard functions in initial values and constants (issue 17): `SHL(WORD#1, 4)`
// was E0313 (missing support). Each initial value is the value the same expression has at run
// time.
TEST(ConstantInitialValues, StandardFunctionsFoldAsTheyComputeAtRunTime) {
    StProgram run(R"(PROGRAM Main
VAR CONSTANT
    kMask : WORD := SHL(WORD#1, 4);
    kLimit : INT := LIMIT(0, 500, 100);
END_VAR
VAR
    w : WORD := SHL(WORD#1, 4); w_now : WORD;
    masked : WORD := kMask OR 1; masked_now : WORD;
    limited : DINT := kLimit * 2; limited_now : DINT;
    biggest : DINT := MAX(3, 7, -2); biggest_now : DINT;
    rotated : BYTE := ROL(BYTE#1, -1); rotated_now : BYTE;
    chosen : INT := MUX(2, 10, 20, 30); chosen_now : INT;
    narrowed : INT := DINT_TO_INT(70000); narrowed_now : INT;
    rounded : INT := REAL_TO_INT(2.5); rounded_now : INT;
    half : REAL := INT_TO_REAL(3) / 2.0; half_now : REAL;
    cut : DINT := TRUNC(-3.7); cut_now : DINT;
    ok : BOOL := GT(3, 2, 1); ok_now : BOOL;
    flipped : WORD := NOT(IN := kMask); flipped_now : WORD;
END_VAR
w_now := SHL(WORD#1, 4);
masked_now := kMask OR 1;
limited_now := kLimit * 2;
biggest_now := MAX(3, 7, -2);
rotated_now := ROL(BYTE#1, -1);
chosen_now := MUX(2, 10, 20, 30);
narrowed_now := DINT_TO_INT(70000);
rounded_now := REAL_TO_INT(2.5);
half_now := INT_TO_REAL(3) / 2.0;
cut_now := TRUNC(-3.7);
ok_now := GT(3, 2, 1);
flipped_now := NOT(IN := kMask);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::uint16_t>("Main.w"), 16);
    EXPECT_EQ(run.get<std::uint16_t>("Main.masked"), 17);
    EXPECT_EQ(run.get<std::int32_t>("Main.limited"), 200);
    EXPECT_EQ(run.get<std::int32_t>("Main.biggest"), 7);
    EXPECT_EQ(run.get<std::uint8_t>("Main.rotated"), 0x80);
    EXPECT_EQ(run.get<std::int16_t>("Main.chosen"), 30);
    EXPECT_EQ(run.get<std::int16_t>("Main.narrowed"), 4464);
    EXPECT_EQ(run.get<std::int16_t>("Main.rounded"), 2);
    EXPECT_EQ(run.get<float>("Main.half"), 1.5F);
    EXPECT_EQ(run.get<std::int32_t>("Main.cut"), -3);
    EXPECT_EQ(run.get<std::uint8_t>("Main.ok"), 1);
    EXPECT_EQ(run.get<std::uint16_t>("Main.flipped"), 0xFFEF);
    for (const char* name : {"w", "masked", "flipped"}) {
        EXPECT_EQ(run.get<std::uint16_t>(std::string("Main.") + name),
                  run.get<std::uint16_t>(std::string("Main.") + name + "_now"))
            << name;
    }
    for (const char* name : {"limited", "biggest", "cut"}) {
        EXPECT_EQ(run.get<std::int32_t>(std::string("Main.") + name),
                  run.get<std::int32_t>(std::string("Main.") + name + "_now"))
            << name;
    }
    for (const char* name : {"chosen", "narrowed", "rounded"}) {
        EXPECT_EQ(run.get<std::int16_t>(std::string("Main.") + name),
                  run.get<std::int16_t>(std::string("Main.") + name + "_now"))
            << name;
    }
    EXPECT_EQ(run.get<std::uint8_t>("Main.rotated"), run.get<std::uint8_t>("Main.rotated_now"));
    EXPECT_EQ(run.get<float>("Main.half"), run.get<float>("Main.half_now"));
    EXPECT_EQ(run.get<std::uint8_t>("Main.ok"), run.get<std::uint8_t>("Main.ok_now"));
}

} // namespace
} // namespace eposp::compiler::test
