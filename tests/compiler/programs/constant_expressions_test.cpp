// The typing stage's constant of an expression (TypedProgram::constant_of) is the value the VM
// computes for it at run time (issue 17): operators (small integers in DINT inside an
// expression, each operation wrapping at its width), conversions and the pure standard
// functions. Each expression is assigned in a program that runs, and its constant compared with
// the value the scan stored.

#include "codegen_harness.hpp"
#include "typing_helpers.hpp"

#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace eposp::compiler::test {
namespace {

/// What an expression's value is read back as: stored into a LINT, ULINT, LWORD, LREAL, BOOL,
/// TIME, STRING[100] or WSTRING[100] variable, which every type of its kind widens into exactly
/// (every text here is shorter).
enum class Kind { Signed, Unsigned, Bits, Real, Bool, Time, Text, Wide };

struct Folded {
    Kind kind;
    std::string expression;
};

const char* variable_type(Kind kind) {
    switch (kind) {
    case Kind::Signed:
        return "LINT";
    case Kind::Unsigned:
        return "ULINT";
    case Kind::Bits:
        return "LWORD";
    case Kind::Real:
        return "LREAL";
    case Kind::Bool:
        return "BOOL";
    case Kind::Text:
        return "STRING[100]";
    case Kind::Wide:
        return "WSTRING[100]";
    default:
        return "TIME";
    }
}

const std::vector<Folded> kExpressions = {
    // INT arithmetic: one operation wraps at INT, an operand inside an expression is DINT.
    {Kind::Signed, "kI + kI"},
    {Kind::Signed, "(kI + kI) / 2"},
    {Kind::Signed, "kI * 3 MOD 1000"},
    {Kind::Signed, "INT_TO_DINT(kI + kI)"},
    {Kind::Signed, "-kI - kI"},
    {Kind::Signed, "kMinD / -1"},
    {Kind::Signed, "kMinD MOD -1"},
    {Kind::Signed, "-kMinD"},
    {Kind::Signed, "-7 MOD 3"},
    {Kind::Signed, "7 / -2"},
    {Kind::Signed, "kMaxD + 1"},
    {Kind::Signed, "NOT kI"},
    {Kind::Signed, "kI OR kI * 2"},
    {Kind::Signed, "SINT#100 + SINT#100"},
    {Kind::Signed, "ABS(kMinI)"},
    {Kind::Signed, "ABS(-5)"},
    {Kind::Signed, "MIN(3, -2, 5)"},
    {Kind::Signed, "MAX(kI, 5)"},
    {Kind::Signed, "LIMIT(0, 500, 100)"},
    {Kind::Signed, "LIMIT(0, -5, 100)"},
    {Kind::Signed, "SEL(TRUE, 1, 2)"},
    {Kind::Signed, "MUX(2, 10, 20, 30)"},
    {Kind::Signed, "MUX(7, 10, 20, 30)"},
    {Kind::Signed, "MUX(-1, 10, 20, 30)"},
    {Kind::Signed, "ADD(kI, kI, 1)"},
    {Kind::Signed, "MUL(kI, 2)"},
    {Kind::Signed, "SUB(1, 2)"},
    {Kind::Signed, "DIV(-7, 2)"},
    {Kind::Signed, "MOD(-7, 2)"},
    {Kind::Signed, "MOVE(kI)"},
    {Kind::Signed, "REAL_TO_INT(2.5)"},
    {Kind::Signed, "REAL_TO_INT(3.5)"},
    {Kind::Signed, "REAL_TO_INT(-2.5)"},
    {Kind::Signed, "LREAL_TO_INT(1.0E30)"},
    {Kind::Signed, "LREAL_TO_DINT(1234566.5)"},
    {Kind::Signed, "TRUNC(-3.7)"},
    {Kind::Signed, "TRUNC(1.0E10)"},
    {Kind::Signed, "DINT_TO_INT(70000)"},
    {Kind::Signed, "UDINT_TO_LINT(DINT_TO_UDINT(-1))"},
    {Kind::Signed, "TO_SINT(200)"},
    {Kind::Signed, "BOOL_TO_INT(TRUE)"},
    {Kind::Signed, "SHL(INT#1, 15)"},
    {Kind::Signed, "SHR(INT#-1, 1)"},
    {Kind::Signed, "ROL(SINT#-128, 1)"},
    {Kind::Signed, "SHL(DINT#1, kI)"},
    {Kind::Unsigned, "UINT#65535 + 1"},
    {Kind::Unsigned, "UDINT#0 - 1"},
    {Kind::Unsigned, "(kU * kU) / 2"},
    {Kind::Unsigned, "MAX(USINT#3, USINT#200)"},
    {Kind::Unsigned, "ULINT#18446744073709551615 / 3"},
    {Kind::Bits, "SHL(WORD#1, 4)"},
    {Kind::Bits, "SHL(DWORD#1, 32)"},
    {Kind::Bits, "SHL(DWORD#1, 4294967297)"},
    {Kind::Bits, "SHL(kB, -1)"},
    {Kind::Bits, "ROL(DWORD#1, 33)"},
    {Kind::Bits, "ROL(DWORD#1, 4294967297)"},
    {Kind::Bits, "ROL(BYTE#1, -1)"},
    {Kind::Bits, "ROR(BYTE#1, 1)"},
    {Kind::Bits, "SHR(LWORD#16#8000000000000000, 63)"},
    {Kind::Bits, "NOT kB"},
    {Kind::Bits, "NOT(IN := kB)"},
    {Kind::Bits, "kB XOR 16#FF"},
    {Kind::Bits, "DWORD#16#F0 AND 16#3C OR 1"},
    {Kind::Bits, "AND(kB, 16#3, 16#7)"},
    {Kind::Bits, "WORD_TO_BYTE(16#1234)"},
    {Kind::Bits, "INT_TO_WORD(-1)"},
    {Kind::Bits, "kB * 32"},
    {Kind::Real, "1.0 / 3.0"},
    {Kind::Real, "REAL#1.0 / 3.0"},
    {Kind::Real, "REAL#16777216.0 + 1.0 + 1.0"},
    {Kind::Real, "INT_TO_REAL(kI)"},
    {Kind::Real, "DINT_TO_REAL(16777217)"},
    {Kind::Real, "LINT_TO_REAL(kBig)"},
    {Kind::Real, "ABS(-2.5)"},
    {Kind::Real, "-kR * 2.0"},
    {Kind::Real, "MAX(1.5, 2.5, -1.0)"},
    {Kind::Real, "LIMIT(0.0, 7.5, 5.0)"},
    {Kind::Real, "DINT_TO_LREAL(7) / 2.0"},
    {Kind::Real, "DINT_TO_LREAL(kSeven / 2)"},
    {Kind::Bool, "kI > 5"},
    {Kind::Bool, "kI + kI > 0"},
    // A negation of small integers is computed in DINT inside an expression too.
    {Kind::Bool, "-kMinI > 0"},
    {Kind::Bool, "-kU < 0"},
    {Kind::Bool, "-(kI * 2) < -32768"},
    {Kind::Signed, "(-kMinI + 1) / 2"},
    {Kind::Signed, "-(-kMinI) / 2"},
    {Kind::Signed, "-kMinI"},
    {Kind::Unsigned, "-kU"},
    {Kind::Bool, "-USINT#5 < 0"},
    {Kind::Bool, "GT(3, 2, 1)"},
    {Kind::Bool, "GT(3, 2, 2)"},
    {Kind::Bool, "EQ(kI, 30000)"},
    {Kind::Bool, "NOT TRUE"},
    {Kind::Bool, "NOT(IN := FALSE)"},
    {Kind::Bool, "TRUE XOR FALSE"},
    {Kind::Bool, "TRUE AND NOT FALSE OR FALSE"},
    {Kind::Bool, "SEL(FALSE, TRUE, FALSE)"},
    {Kind::Bool, "INT_TO_BOOL(5)"},
    {Kind::Bool, "T#1s < T#2s"},
    {Kind::Time, "T#1ms * 4"},
    {Kind::Time, "kT / -1"},
    {Kind::Time, "T#1s - T#1500ms"},
    {Kind::Time, "MAX(T#1s, T#2s)"},
    {Kind::Time, "DT#2020-01-01-00:00:00 - DT#2019-12-31-23:00:00"},
    // The real functions (vm/stdlib/real_functions.hpp), REAL's in single precision; an
    // integer input is taken as LREAL; infinities are constants.
    {Kind::Real, "SQRT(2.0)"},
    {Kind::Real, "SQRT(REAL#2.0)"},
    {Kind::Real, "SQRT(16)"},
    {Kind::Real, "SQRT(SQRT(kR))"},
    {Kind::Real, "LN(10.0)"},
    {Kind::Real, "LN(REAL#10.0)"},
    {Kind::Real, "LN(0.0)"},
    {Kind::Real, "LOG(REAL#7.0)"},
    {Kind::Real, "EXP(1.0)"},
    {Kind::Real, "EXP(kR)"},
    {Kind::Real, "EXP(1000.0)"},
    {Kind::Real, "SIN(kR)"},
    {Kind::Real, "SIN(1.0E22)"},
    {Kind::Real, "COS(1.0)"},
    {Kind::Real, "TAN(REAL#0.5)"},
    {Kind::Real, "ASIN(0.5)"},
    {Kind::Real, "ACOS(REAL#0.25)"},
    {Kind::Real, "ATAN(2.0)"},
    {Kind::Real, "ATAN2(1.0, -1.0)"},
    {Kind::Real, "ATAN2(Y := REAL#1.0, X := kR)"},
    {Kind::Real, "EXPT(2.0, 10)"},
    {Kind::Real, "EXPT(kR, kI)"},
    {Kind::Real, "EXPT(-2.0, 3)"},
    {Kind::Real, "kR ** 2"},
    {Kind::Real, "2.0 ** 0.5"},
    {Kind::Real, "(kI + kI) ** 1.0"},
    {Kind::Signed, "TRUNC(SQRT(17.0))"},
    {Kind::Signed, "REAL_TO_DINT(LN(kR) * 1000.0)"},
    // Conversions to and from the times: TIME and TOD count in ms, DATE and DT in s, the long
    // forms in ns; a DATE is the day and a TOD the time of day of any other time (DT_TO_DATE).
    {Kind::Signed, "TIME_TO_DINT(T#1.5s)"},
    {Kind::Signed, "TIME_TO_DINT(T#-1.5ms)"},
    {Kind::Signed, "TIME_TO_LINT(kT)"},
    {Kind::Signed, "LTIME_TO_LINT(LTIME#1ms)"},
    {Kind::Signed, "TIME_TO_SINT(T#300ms)"},
    {Kind::Real, "TIME_TO_REAL(T#1500ms)"},
    {Kind::Signed, "TOD_TO_DINT(TOD#12:00:00.5)"},
    {Kind::Signed, "DATE_TO_LINT(D#2020-01-02)"},
    {Kind::Signed, "DT_TO_LINT(DT#2020-01-01-10:00:00)"},
    {Kind::Signed, "DATE_TO_LINT(DT_TO_DATE(DT#2020-01-01-10:00:00))"},
    {Kind::Signed, "TOD_TO_LINT(DT_TO_TOD(DT#2020-01-01-10:00:00))"},
    {Kind::Signed, "LTOD_TO_LINT(LDT_TO_LTOD(kLdt))"},
    {Kind::Signed, "LDATE_TO_LINT(LDT_TO_LDATE(kLdt))"},
    {Kind::Signed, "TOD_TO_LINT(TIME_TO_TOD(-kT))"},
    {Kind::Signed, "DATE_TO_LINT(TOD_TO_DATE(TOD#12:00:00))"},
    {Kind::Time, "DINT_TO_TIME(1500)"},
    {Kind::Time, "TO_TIME(kI)"},
    {Kind::Time, "REAL_TO_TIME(2.5)"},
    {Kind::Time, "LINT_TO_TIME(kBig)"},
    {Kind::Signed, "TOD_TO_LINT(DINT_TO_TOD(1000))"},
    {Kind::Signed, "LTIME_TO_LINT(TIME_TO_LTIME(T#1s))"},
    // Table 30: a TIME_OF_DAY wraps at midnight, a TIME times a real rounds to the ns.
    {Kind::Signed, "TOD_TO_LINT(TOD#23:00:00 + T#2h)"},
    {Kind::Signed, "TOD_TO_LINT(TOD#01:00:00 - T#2h)"},
    {Kind::Signed, "DT_TO_LINT(DT#2020-01-01-23:00:00 + T#2h)"},
    {Kind::Time, "T#1s * 1.5"},
    {Kind::Time, "kT * REAL#0.1"},
    {Kind::Time, "T#1s / 3.0"},
    {Kind::Time, "T#1ms * kI"},
    {Kind::Time, "ADD_TIME(T#1s, T#2s)"},
    {Kind::Time, "MUL_TIME(T#1s, 3)"},
    {Kind::Time, "MUL_TIME(T#1s, 0.3)"},
    {Kind::Time, "DIV_TIME(kT, -1)"},
    {Kind::Time, "SUB_DT_DT(DT#2020-01-02-00:00:00, DT#2020-01-01-12:00:00)"},
    {Kind::Time, "SUB_TOD_TOD(TOD#01:00:00, TOD#02:00:00)"},
    {Kind::Signed, "TOD_TO_LINT(ADD_TOD_TIME(TOD#23:59:59, T#2s))"},
    {Kind::Signed, "TOD_TO_LINT(SUB_TOD_TIME(TOD#00:00:01, T#2s))"},
    {Kind::Signed, "DT_TO_LINT(CONCAT_DATE_TOD(D#2020-01-01, TOD#12:00:00))"},
    // The bounds of an array of fixed bounds; ENO of a call without EN; LEN of a literal.
    {Kind::Signed, "LOWER_BOUND(arr, 1)"},
    {Kind::Signed, "UPPER_BOUND(arr, 1)"},
    {Kind::Signed, "UPPER_BOUND(arr, 2)"},
    {Kind::Bits, "SHL(IN := kB, N := 2, ENO => eno)"},
    {Kind::Signed, "ABS(IN := -5, ENO => eno)"},
    {Kind::Bits, "NOT(IN := kB, ENO => eno)"},
    {Kind::Signed, "LEN('hello')"},
    {Kind::Signed, "LEN('')"},
    // The string functions of table 29 (vm/stdlib/text_functions.hpp) on STRING constants: a
    // CONSTANT's text cut at its declared length (kCut is 'abc'), lengths below 0 count as 0,
    // past the end are cut, a position outside selects nothing (INSERT clamps it), a length or
    // position beyond DINT saturates, a result is cut at the capacity it is computed in
    // (CONCAT's at 65535: LEN 65535 as INT is -1), LEN and FIND are INT.
    {Kind::Signed, "LEN(kS)"},
    {Kind::Signed, "LEN(kE)"},
    {Kind::Signed, "LEN(kCut)"},
    {Kind::Signed, "LEN(kLong)"},
    {Kind::Signed, "LEN(CONCAT(kLong, kLong))"},
    {Kind::Signed, "LEN(CONCAT(kLong, kLong, kS))"},
    {Kind::Signed, "LEN(CONCAT(kCut, kCut))"},
    {Kind::Text, "LEFT(kS, 2)"},
    {Kind::Text, "LEFT(kS, 0)"},
    {Kind::Text, "LEFT(kS, -1)"},
    {Kind::Text, "LEFT(kS, 99)"},
    {Kind::Text, "LEFT(kS, kBig)"},
    {Kind::Text, "LEFT(kS, kMinD)"},
    {Kind::Text, "LEFT(kS, kSi + kSi)"},
    {Kind::Text, "LEFT(kE, 3)"},
    {Kind::Text, "LEFT(kLong, 3)"},
    {Kind::Text, "LEFT(IN := kS, L := 2, ENO => eno)"},
    {Kind::Text, "RIGHT(kS, 2)"},
    {Kind::Text, "RIGHT(kS, -3)"},
    {Kind::Text, "RIGHT(kS, 10)"},
    {Kind::Text, "RIGHT(kCut, 2)"},
    {Kind::Text, "MID(kS, 2, 2)"},
    {Kind::Text, "MID(kS, 2, 10)"},
    {Kind::Text, "MID(kS, 0, 2)"},
    {Kind::Text, "MID(kS, 6, 2)"},
    {Kind::Text, "MID(kS, -1, 2)"},
    {Kind::Text, "MID(kS, 2, 5)"},
    {Kind::Text, "MID(kS, 2, 6)"},
    {Kind::Text, "MID(kS, 2, 0)"},
    {Kind::Text, "MID(kS, 2, -1)"},
    {Kind::Text, "MID(kS, kU, 1)"},
    {Kind::Text, "MID(P := 3, IN := kS, L := 2)"},
    {Kind::Text, "CONCAT(kS, 'x')"},
    {Kind::Text, "CONCAT(kE, kE)"},
    {Kind::Text, "CONCAT(kS, kCut, kS)"},
    {Kind::Text, "CONCAT(kCut, ' ', kS, '!')"},
    {Kind::Text, "INSERT(kS, 'XY', 2)"},
    {Kind::Text, "INSERT(kS, 'XY', 0)"},
    {Kind::Text, "INSERT(kS, 'XY', -4)"},
    {Kind::Text, "INSERT(kS, 'XY', 5)"},
    {Kind::Text, "INSERT(kS, 'XY', 99)"},
    {Kind::Text, "INSERT(kE, kS, 1)"},
    {Kind::Text, "INSERT(kCut, kCut, 1)"},
    {Kind::Text, "DELETE(kS, 2, 2)"},
    {Kind::Text, "DELETE(kS, 2, 0)"},
    {Kind::Text, "DELETE(kS, 2, 6)"},
    {Kind::Text, "DELETE(kS, 2, -2)"},
    {Kind::Text, "DELETE(kS, 0, 2)"},
    {Kind::Text, "DELETE(kS, 2, 5)"},
    {Kind::Text, "DELETE(kS, 9, 1)"},
    {Kind::Text, "DELETE(kS, -1, 1)"},
    {Kind::Text, "REPLACE(kS, 'XY', 2, 2)"},
    {Kind::Text, "REPLACE(kS, 'XY', 0, 2)"},
    {Kind::Text, "REPLACE(kS, 'XY', -1, 2)"},
    {Kind::Text, "REPLACE(kS, 'XY', 9, 1)"},
    {Kind::Text, "REPLACE(kS, 'XY', 2, 6)"},
    {Kind::Text, "REPLACE(kS, 'XY', 2, 0)"},
    {Kind::Text, "REPLACE(kS, kE, 1, 1)"},
    {Kind::Text, "REPLACE(kCut, kS, 1, 3)"},
    {Kind::Signed, "FIND(kS, 'l')"},
    {Kind::Signed, "FIND(kS, 'lo')"},
    {Kind::Signed, "FIND(kS, 'z')"},
    {Kind::Signed, "FIND(kS, kE)"},
    {Kind::Signed, "FIND(kE, 'a')"},
    {Kind::Signed, "FIND(kE, kE)"},
    {Kind::Signed, "FIND(kS, 'hello!')"},
    {Kind::Signed, "FIND(kS, kS)"},
    {Kind::Signed, "FIND(kCut, 'c')"},
    {Kind::Signed, "FIND(kCut, 'd')"},
    {Kind::Text, "MID(CONCAT(kS, kS), 3, 4)"},
    {Kind::Text, "LEFT(REPLACE(kS, kCut, 1, 1), 4)"},
    {Kind::Text, "SEL(TRUE, kCut, kS)"},
    {Kind::Text, "MUX(1, kS, kCut)"},
    {Kind::Text, "kCut"},
    // The same natives of WSTRING (LEFT_WSTRING...), on UTF-16 units.
    {Kind::Signed, "LEN(kW)"},
    {Kind::Signed, "LEN(kWCut)"},
    {Kind::Signed, "LEN(\"\")"},
    {Kind::Signed, "FIND(kW, \"$00E9l\")"},
    {Kind::Signed, "FIND(kW, \"z\")"},
    {Kind::Wide, "kWCut"},
    {Kind::Wide, "LEFT(kW, 2)"},
    {Kind::Wide, "RIGHT(kW, -1)"},
    {Kind::Wide, "MID(kW, 3, 2)"},
    {Kind::Wide, "MID(kW, 1, 9)"},
    {Kind::Wide, "CONCAT(kW, kWCut, \"!\")"},
    {Kind::Wide, "INSERT(kW, kWCut, 99)"},
    {Kind::Wide, "DELETE(kW, 2, 2)"},
    {Kind::Wide, "REPLACE(kWCut, kW, 1, 2)"},
    {Kind::Wide, "REPLACE(kW, \"XY\", 0, 2)"},
    // Comparisons of texts (EQ_STRING, LT_WSTRING...: text_order, the codes unsigned), of a
    // CONSTANT's text cut at its declared length; extensible ones pair by pair (table 28);
    // MAX, MIN and LIMIT compare so too. CHAR and WCHAR compare their codes.
    {Kind::Bool, "'abc' < 'abd'"},
    {Kind::Bool, "'abc' = 'abc'"},
    {Kind::Bool, "'abc' <> 'abc'"},
    {Kind::Bool, "'ab' < 'abc'"},
    {Kind::Bool, "'abc' <= 'ab'"},
    {Kind::Bool, "kE < 'a'"},
    {Kind::Bool, "kE = ''"},
    {Kind::Bool, "kE >= kE"},
    {Kind::Bool, "kS > 'hello'"},
    {Kind::Bool, "kS >= 'hello'"},
    {Kind::Bool, "kCut = 'abc'"},
    {Kind::Bool, "kCut <> 'abcdef'"},
    {Kind::Bool, "kCut < kLong"},
    {Kind::Bool, "'z' < kHigh"},
    {Kind::Bool, "kHigh > '$7F'"},
    {Kind::Bool, "kHigh <= '$E9t'"},
    {Kind::Bool, "CONCAT(kCut, 'd') = LEFT(kCut, 5)"},
    {Kind::Bool, "EQ(kS, 'hello', kS)"},
    {Kind::Bool, "EQ(kS, 'hello', kCut)"},
    {Kind::Bool, "LT('a', 'b', 'c')"},
    {Kind::Bool, "LT('a', 'c', 'b')"},
    {Kind::Bool, "GE(kS, kS, kE)"},
    {Kind::Bool, "GT(kHigh, kS)"},
    {Kind::Bool, "LE(kCut, kCut)"},
    {Kind::Bool, "NE(kCut, 'abcdef')"},
    {Kind::Bool, "kW > \"h\""},
    {Kind::Bool, "\"$00E9\" > \"z\""},
    {Kind::Bool, "\"$20AC\" > \"$00FF\""},
    {Kind::Bool, "kWCut = \"abc\""},
    {Kind::Bool, "EQ(kW, kW, \"h$00E9llo\")"},
    {Kind::Bool, "LT(kWCut, kW)"},
    {Kind::Bool, "CHAR#'a' < CHAR#'b'"},
    {Kind::Bool, "kC = CHAR#'q'"},
    {Kind::Bool, "CHAR#'$E9' > CHAR#'z'"},
    {Kind::Bool, "WCHAR#\"$00E9\" > WCHAR#\"z\""},
    {Kind::Bool, "kWc = WCHAR#\"$00E9\""},
    {Kind::Bool, "GT(WCHAR#\"c\", WCHAR#\"b\", WCHAR#\"a\")"},
    {Kind::Text, "MAX('abc', 'abd', 'ab')"},
    {Kind::Text, "MIN(kS, kCut, kHigh)"},
    {Kind::Text, "LIMIT('b', kS, 'd')"},
    {Kind::Wide, "MAX(kW, kWCut)"},
    // Conversions to texts (value_text.hpp's forms): integers in decimal, reals in the shortest
    // form that reads back (REAL's in single precision), times in every unit.
    {Kind::Text, "INT_TO_STRING(-42)"},
    {Kind::Text, "INT_TO_STRING(kI)"},
    {Kind::Text, "DINT_TO_STRING(kMinD)"},
    {Kind::Text, "LINT_TO_STRING(kBig)"},
    {Kind::Text, "SINT_TO_STRING(kSi + kSi)"},
    {Kind::Text, "UINT_TO_STRING(kU)"},
    {Kind::Text, "ULINT_TO_STRING(ULINT#18446744073709551615)"},
    {Kind::Text, "BYTE_TO_STRING(16#FF)"},
    {Kind::Text, "LWORD_TO_STRING(LWORD#16#8000000000000000)"},
    {Kind::Text, "BOOL_TO_STRING(TRUE)"},
    {Kind::Text, "BOOL_TO_STRING(kI < 0)"},
    {Kind::Text, "REAL_TO_STRING(kR)"},
    {Kind::Text, "REAL_TO_STRING(1.0 / 3.0)"},
    {Kind::Text, "LREAL_TO_STRING(1.0 / 3.0)"},
    {Kind::Text, "LREAL_TO_STRING(0.1)"},
    {Kind::Text, "LREAL_TO_STRING(-2.0)"},
    {Kind::Text, "LREAL_TO_STRING(1.0E20)"},
    {Kind::Text, "LREAL_TO_STRING(-1.5E-7)"},
    {Kind::Text, "LREAL_TO_STRING(-0.0)"},
    {Kind::Text, "LREAL_TO_STRING(EXP(1000.0))"},
    {Kind::Text, "LREAL_TO_STRING(-EXP(1000.0))"},
    {Kind::Text, "REAL_TO_STRING(REAL#16777217.0)"},
    {Kind::Text, "TIME_TO_STRING(T#1d2h3m4s5ms)"},
    {Kind::Text, "TIME_TO_STRING(T#-1.5s)"},
    {Kind::Text, "TIME_TO_STRING(T#0s)"},
    {Kind::Text, "TIME_TO_STRING(kT)"},
    {Kind::Text, "LTIME_TO_STRING(LTIME#1us2ns)"},
    {Kind::Text, "DATE_TO_STRING(D#2020-02-29)"},
    {Kind::Text, "TOD_TO_STRING(TOD#12:34:56.789)"},
    {Kind::Text, "DT_TO_STRING(DT#1969-12-31-23:59:59.5)"},
    {Kind::Text, "LDATE_TO_STRING(LDATE#2024-01-31)"},
    {Kind::Text, "LTOD_TO_STRING(LTOD#12:34:56.123456789)"},
    {Kind::Text, "LDT_TO_STRING(LDT#1969-12-31-23:59:59.5)"},
    {Kind::Text, "TO_STRING(kLdt)"},
    {Kind::Text, "TO_STRING(kI)"},
    {Kind::Text, "TO_STRING(-7)"},
    {Kind::Text, "CHAR_TO_STRING(kC)"},
    {Kind::Text, "CHAR_TO_STRING(CHAR#'$E9')"},
    {Kind::Text, "CHAR_TO_STRING(STRING_TO_CHAR(kE))"},
    {Kind::Text, "CONCAT(INT_TO_STRING(kI), '/', TIME_TO_STRING(kT))"},
    {Kind::Signed, "LEN(LREAL_TO_STRING(1.0 / 3.0))"},
    // Conversions from texts: as much of the form as is there, 0 for what does not start one;
    // integers wrap at the type's width.
    {Kind::Signed, "STRING_TO_INT('42')"},
    {Kind::Signed, "STRING_TO_INT(kNumber)"},
    {Kind::Signed, "STRING_TO_INT('16#FF')"},
    {Kind::Signed, "STRING_TO_INT('2#1010_1010')"},
    {Kind::Signed, "STRING_TO_INT('12abc')"},
    {Kind::Signed, "STRING_TO_INT('abc')"},
    {Kind::Signed, "STRING_TO_INT(kE)"},
    {Kind::Signed, "STRING_TO_INT('+7')"},
    {Kind::Signed, "STRING_TO_INT('99999')"},
    {Kind::Signed, "STRING_TO_SINT('-129')"},
    {Kind::Signed, "STRING_TO_LINT('-9223372036854775808')"},
    {Kind::Signed, "STRING_TO_DINT(kHigh)"},
    {Kind::Signed, "STRING_TO_DINT(INT_TO_STRING(kI))"},
    {Kind::Signed, "TO_INT('123')"},
    {Kind::Unsigned, "STRING_TO_UDINT('-1')"},
    {Kind::Unsigned, "STRING_TO_ULINT('18446744073709551615')"},
    {Kind::Bits, "STRING_TO_WORD('16#ABCD')"},
    {Kind::Bits, "STRING_TO_BYTE('300')"},
    {Kind::Real, "STRING_TO_REAL('1.1')"},
    {Kind::Real, "STRING_TO_LREAL('1.1')"},
    {Kind::Real, "STRING_TO_LREAL(kReal)"},
    {Kind::Real, "STRING_TO_LREAL('-0.5xyz')"},
    {Kind::Real, "STRING_TO_LREAL('x1')"},
    {Kind::Real, "STRING_TO_LREAL(LREAL_TO_STRING(1.0 / 3.0))"},
    {Kind::Bool, "STRING_TO_BOOL('TRUE')"},
    {Kind::Bool, "STRING_TO_BOOL('true')"},
    {Kind::Bool, "STRING_TO_BOOL('0')"},
    {Kind::Bool, "STRING_TO_BOOL('5')"},
    {Kind::Bool, "STRING_TO_BOOL('yes')"},
    {Kind::Time, "STRING_TO_TIME('T#1s500ms')"},
    {Kind::Time, "STRING_TO_TIME('-2.5m')"},
    {Kind::Time, "STRING_TO_TIME('1h_30m')"},
    {Kind::Time, "STRING_TO_TIME(kE)"},
    {Kind::Signed, "LTIME_TO_LINT(STRING_TO_LTIME('LTIME#3ns'))"},
    {Kind::Signed, "DATE_TO_LINT(STRING_TO_DATE('D#2020-01-02'))"},
    {Kind::Signed, "DATE_TO_LINT(STRING_TO_DATE('2020-02-30'))"},
    {Kind::Signed, "TOD_TO_LINT(STRING_TO_TOD('TOD#12:00:00.25'))"},
    {Kind::Signed, "DT_TO_LINT(STRING_TO_DT('DT#2020-01-01-10:00:00'))"},
    {Kind::Signed, "LDATE_TO_LINT(STRING_TO_LDATE('LDATE#2020-01-02'))"},
    {Kind::Signed, "LTOD_TO_LINT(STRING_TO_LTOD('LTOD#12:00:00.000000025'))"},
    {Kind::Signed, "LDT_TO_LINT(STRING_TO_LDT(LDT_TO_STRING(kLdt)))"},
    {Kind::Unsigned, "CHAR_TO_USINT(STRING_TO_CHAR(kS))"},
    {Kind::Unsigned, "CHAR_TO_USINT(STRING_TO_CHAR(kHigh))"},
    {Kind::Unsigned, "CHAR_TO_USINT(STRING_TO_CHAR(kE))"},
    // WCHAR and WSTRING: a WCHAR literal is its code; a unit above 255 is '?' in a STRING.
    {Kind::Unsigned, "WCHAR_TO_UINT(WCHAR#\"$20AC\")"},
    {Kind::Unsigned, "WCHAR_TO_UINT(kWc)"},
    {Kind::Unsigned, "WCHAR_TO_UINT(WSTRING_TO_WCHAR(kW))"},
    {Kind::Unsigned, "WCHAR_TO_UINT(WSTRING_TO_WCHAR(\"\"))"},
    {Kind::Wide, "WCHAR_TO_WSTRING(kWc)"},
    {Kind::Wide, "WCHAR_TO_WSTRING(WCHAR#\"y\")"},
    {Kind::Wide, "STRING_TO_WSTRING(kHigh)"},
    {Kind::Wide, "STRING_TO_WSTRING(kE)"},
    {Kind::Wide, "TO_WSTRING(kCut)"},
    {Kind::Text, "WSTRING_TO_STRING(kW)"},
    {Kind::Text, "WSTRING_TO_STRING(\"a$20ACb\")"},
    {Kind::Text, "TO_STRING(kWCut)"},
    {Kind::Signed, "LEN(WSTRING_TO_STRING(kW))"},
    // A text result is cut at the capacity of its type, STRING[80] or WSTRING[80], also where
    // it is stored straight into the longer variable that reads it back here.
    {Kind::Wide, "STRING_TO_WSTRING(kLong)"},
    {Kind::Text, "WSTRING_TO_STRING(STRING_TO_WSTRING(kLong))"},
    {Kind::Text, "TO_STRING(kLong)"},
    {Kind::Text, "STRING_TO_STRING(kLong)"},
    {Kind::Text, "TO_STRING(kCut)"},
    {Kind::Wide, "TO_WSTRING(kW)"},
    {Kind::Signed, "LEN(TO_STRING(kLong))"},
    {Kind::Text, "CONCAT(TO_STRING(kCut), TO_STRING(kS))"},
};

/// The operands the expressions name, CONSTANTs (`VAR CONSTANT`) or variables (`VAR`).
std::string operands(const char* section) {
    std::string text = std::string(section) + R"(
    kI : INT := 30000; kMinI : INT := -32768; kMinD : DINT := -2147483648;
    kMaxD : DINT := 2147483647; kU : UINT := 60000; kB : BYTE := 16#0F;
    kR : REAL := 1.1; kSeven : DINT := 7; kBig : LINT := 9007199254740993; kT : TIME := T#5ms;
    kS : STRING := 'hello'; kE : STRING := ''; kCut : STRING[3] := 'abcdef'; kSi : SINT := 100;
    kW : WSTRING := "h$00E9llo"; kWCut : WSTRING[3] := "abcdef"; kHigh : STRING := '$E9t$E9';
    kNumber : STRING := '  -17'; kReal : STRING := '1.5E3'; kC : CHAR := CHAR#'q';
    kWc : WCHAR := WCHAR#"$00E9"; kLdt : LDT := LDT#2024-01-31-12:34:56.000000001;
    kLong : STRING[20000] := ')";
    text += std::string(20000, 'x');
    return text + R"(';
END_VAR
VAR arr : ARRAY[-2..5, 1..3] OF INT; eno : BOOL; END_VAR
)";
}

/// PROGRAM Main assigning each expression to its variable, the operands in `section`.
std::string program(const char* section) {
    std::string declarations = "VAR\n";
    std::string body;
    for (std::size_t i = 0; i < kExpressions.size(); ++i) {
        declarations +=
            "    x" + std::to_string(i) + " : " + variable_type(kExpressions[i].kind) + ";\n";
        body += "x" + std::to_string(i) + " := " + kExpressions[i].expression + ";\n";
    }
    return "PROGRAM Main\n" + operands(section) + declarations + "END_VAR\n" + body +
           "END_PROGRAM\n";
}

// Each constant is compared with what the VM computes for the expression, its operands
// CONSTANTs and again variables (which no stage can fold).
class ConstantExpressions : public ::testing::TestWithParam<const char*> {};

TEST_P(ConstantExpressions, TheTypingStagesConstantIsTheValueTheVmComputes) {
    const auto typed = type_source(program("VAR CONSTANT"));
    ASSERT_TRUE(typed->front_end->program) << typed->errors();
    StProgram run(program(GetParam()));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    for (std::size_t i = 0; i < kExpressions.size(); ++i) {
        const Folded& folded = kExpressions[i];
        const std::string path = "Main.x" + std::to_string(i);
        const types::Constant* constant = typed->program().constant_of(typed->value(i));
        ASSERT_NE(constant, nullptr) << folded.expression;
        switch (folded.kind) {
        case Kind::Signed:
        case Kind::Time:
            ASSERT_TRUE(std::holds_alternative<std::int64_t>(*constant)) << folded.expression;
            EXPECT_EQ(std::get<std::int64_t>(*constant), run.get<std::int64_t>(path))
                << folded.expression;
            break;
        case Kind::Unsigned:
        case Kind::Bits:
            ASSERT_TRUE(std::holds_alternative<std::uint64_t>(*constant)) << folded.expression;
            EXPECT_EQ(std::get<std::uint64_t>(*constant), run.get<std::uint64_t>(path))
                << folded.expression;
            break;
        case Kind::Real:
            ASSERT_TRUE(std::holds_alternative<double>(*constant)) << folded.expression;
            EXPECT_EQ(std::get<double>(*constant), run.get<double>(path)) << folded.expression;
            break;
        case Kind::Bool:
            ASSERT_TRUE(std::holds_alternative<bool>(*constant)) << folded.expression;
            EXPECT_EQ(std::get<bool>(*constant), run.get<std::uint8_t>(path) != 0)
                << folded.expression;
            break;
        case Kind::Text:
            ASSERT_TRUE(std::holds_alternative<std::string>(*constant)) << folded.expression;
            EXPECT_EQ(std::get<std::string>(*constant), run.get_string(path)) << folded.expression;
            break;
        case Kind::Wide:
            ASSERT_TRUE(std::holds_alternative<std::u16string>(*constant)) << folded.expression;
            EXPECT_TRUE(std::get<std::u16string>(*constant) == run.get_wstring(path))
                << folded.expression;
            break;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Operands, ConstantExpressions, ::testing::Values("VAR CONSTANT", "VAR"));

// A division by zero is no constant: it stops the task at run time.
TEST(ConstantExpressionsOf, ADivisionByZeroIsNoConstant) {
    const auto typed = type_body("x : DINT; k : DINT;", "x := 1 / (k - k); x := DIV(1, 0);");
    ASSERT_TRUE(typed->front_end->program) << typed->errors();
    EXPECT_EQ(typed->program().constant_of(typed->value(1)), nullptr);
}

// An arithmetic operand an operator holds in DINT has, as its constant, the value the operator
// computes with: `USINT#255 + 1` feeds `/` as 256, not as its USINT 0.
TEST(ConstantExpressions, AnOperandHeldInDintHasTheValueItsOperatorComputesWith) {
    const auto typed = type_body("x : LINT;", "x := (USINT#255 + 1) / 2;");
    ASSERT_TRUE(typed->front_end->program) << typed->errors();
    const auto& quotient = std::get<ast::BinaryExpression>(typed->value(0).node);
    const types::Constant* held = typed->program().constant_of(*quotient.left);
    ASSERT_NE(held, nullptr);
    EXPECT_EQ(*held, types::Constant{std::int64_t{256}});
    StProgram run("PROGRAM Main VAR x : LINT; END_VAR x := (USINT#255 + 1) / 2; END_PROGRAM");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int64_t>("Main.x"), 128);
}

// A constant index addresses the element the same index computed at run time does: `UINT#0 - 1`
// is the UINT 65535, as `u - 1` of a UINT u = 0 is, not -1.
TEST(ConstantExpressions, AConstantIndexIsTheIndexTheVmComputes) {
    StProgram run(R"(PROGRAM Main
VAR a : ARRAY[-1..65535] OF INT; u : UINT; folded : LINT; computed : LINT; END_VAR
a[-1] := 1; a[65535] := 2;
folded := a[UINT#0 - 1];
computed := a[u - 1];
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int64_t>("Main.computed"), 2);
    EXPECT_EQ(run.get<std::int64_t>("Main.folded"), 2);
}

// Bounds, subranges, CASE labels and CONSTANTs read the one folder, standard functions
// included, also a CONSTANT a TYPE declared before it uses.
TEST(ConstantExpressions, BoundsSubrangesAndCaseLabelsFoldLikeEveryConstant) {
    StProgram run(R"(TYPE Buffer : ARRAY[0..kSize] OF BYTE; END_TYPE
VAR_GLOBAL CONSTANT
    kSize : INT := SHL(INT#1, 2);
END_VAR
PROGRAM Main
VAR CONSTANT kLast : DINT := kSize * 2 + 1; END_VAR
VAR
    a : ARRAY[0..SHL(1, 3)] OF INT;
    b : ARRAY[0..kLast] OF BYTE;
    buffer : Buffer;
    s : INT(0..SHL(1, 4)) := SHL(1, 4);
    upper : DINT; last : DINT; size : DINT; label : DINT;
END_VAR
upper := UPPER_BOUND(a, 1);
last := UPPER_BOUND(b, 1);
size := UPPER_BOUND(buffer, 1);
CASE s OF
SHL(1, 4): label := 16;
ELSE label := -1;
END_CASE
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int32_t>("Main.upper"), 8);
    EXPECT_EQ(run.get<std::int32_t>("Main.last"), 9);
    EXPECT_EQ(run.get<std::int32_t>("Main.size"), 4);
    EXPECT_EQ(run.get<std::int32_t>("Main.label"), 16);
}

// A real function's NaN (a domain error) is left to run time, as are a DIV_TIME by zero (which
// stops the task), a call with EN and the bounds of an ARRAY[*].
TEST(ConstantExpressionsOf, WhatTheVmDoesNotGiveTheSameWayIsNoConstant) {
    const auto typed = type_source(std::string(R"(
FUNCTION Last : DINT
VAR_IN_OUT a : ARRAY[*] OF INT; END_VAR
Last := UPPER_BOUND(a, 1);
END_FUNCTION
PROGRAM Main
VAR CONSTANT kText : STRING := 'abc'; END_VAR
VAR r : LREAL; t : TIME; n : INT; END_VAR
r := SQRT(-1.0);
r := LN(REAL#-1.0);
r := ACOS(2.0);
r := EXPT(-8.0, 1.0 / 3.0);
r := (-8.0) ** (1.0 / 3.0);
t := DIV_TIME(T#1s, 0);
t := DIV_TIME(T#1s, 0.0);
n := LEN(EN := TRUE, IN := kText);
n := LEN(kText);
n := LEN("abc");
r := SQRT(2.0);
END_PROGRAM
)"));
    ASSERT_TRUE(typed->front_end->program) << typed->errors();
    for (std::size_t i = 0; i < 8; ++i) {
        EXPECT_EQ(typed->program().constant_of(typed->value(i)), nullptr) << i;
    }
    for (std::size_t i = 8; i < 11; ++i) {
        EXPECT_NE(typed->program().constant_of(typed->value(i)), nullptr) << i;
    }
    const ast::Pou& last = typed->front_end->units.back().pous.front();
    EXPECT_EQ(typed->program().constant_of(
                  *std::get<ast::AssignmentStatement>(last.body.at(0).node).value),
              nullptr);
}

// An initial value takes the constant the typing stage folds: these were refused (E0313)
// before the real functions and table 30 were folded.
TEST(ConstantExpressionsOf, InitialValuesTakeTheFoldedConstants) {
    StProgram run(R"(
PROGRAM Main
VAR
    t : TIME := T#1s * 1.5;
    d : TOD := TOD#23:00:00 + T#2h;
    r : LREAL := SQRT(2.0);
    n : DINT := TIME_TO_DINT(T#2s);
END_VAR
t := t;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(run.get<std::int64_t>("Main.t"), 1'500'000'000);
    EXPECT_EQ(run.get<std::int64_t>("Main.d"), 3'600'000'000'000);
    EXPECT_EQ(run.get<double>("Main.r"), std::sqrt(2.0));
    EXPECT_EQ(run.get<std::int32_t>("Main.n"), 2000);
}

// A STRING's or WSTRING's initial value takes the folded text: a string function of constants
// (E0313 before), a CONSTANT's text cut at its declared length (its literal's whole text
// before), cut again at the variable's capacity as a literal is; the values are the VM's for
// the same calls.
TEST(ConstantExpressionsOf, AStringsInitialValueIsTheFoldedText) {
    StProgram run(R"(
VAR_GLOBAL CONSTANT kName : STRING[3] := 'abcdef'; END_VAR
PROGRAM Main
VAR CONSTANT kHello : STRING := 'hello'; kWide : WSTRING[2] := "xyz"; END_VAR
VAR
    joined : STRING := CONCAT('a', 'b', kName);
    name : STRING[10] := kName;
    cut : STRING[4] := CONCAT(kHello, kName);
    part : STRING := MID(REPLACE(kHello, 'XY', 2, 2), 3, 2);
    wide : WSTRING[4] := CONCAT("$00E9", kWide);
    length : INT := LEN(CONCAT(kName, kHello));
    found : INT := FIND(kHello, 'l');
    joined_now : STRING; name_now : STRING[10]; cut_now : STRING[4]; part_now : STRING;
    length_now : INT; found_now : INT; wide_now : WSTRING[4];
END_VAR
joined_now := CONCAT('a', 'b', kName);
name_now := kName;
cut_now := CONCAT(kHello, kName);
part_now := MID(REPLACE(kHello, 'XY', 2, 2), 3, 2);
length_now := LEN(CONCAT(kName, kHello));
found_now := FIND(kHello, 'l');
wide_now := CONCAT("$00E9", kWide);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(run.get_string("Main.joined"), "ababc");
    EXPECT_EQ(run.get_string("Main.name"), "abc");
    EXPECT_EQ(run.get_string("Main.cut"), "hell");
    EXPECT_EQ(run.get_string("Main.part"), "XYl");
    EXPECT_TRUE(run.get_wstring("Main.wide") == u"\u00E9xy");
    EXPECT_EQ(run.get<std::int16_t>("Main.length"), 8);
    EXPECT_EQ(run.get<std::int16_t>("Main.found"), 3);
    ASSERT_TRUE(run.scans(1));
    for (const char* name : {"joined", "name", "cut", "part"}) {
        const std::string path = std::string("Main.") + name;
        EXPECT_EQ(run.get_string(path), run.get_string(path + "_now")) << name;
    }
    EXPECT_EQ(run.get<std::int16_t>("Main.length"), run.get<std::int16_t>("Main.length_now"));
    EXPECT_EQ(run.get<std::int16_t>("Main.found"), run.get<std::int16_t>("Main.found_now"));
    EXPECT_TRUE(run.get_wstring("Main.wide") == run.get_wstring("Main.wide_now"));
}

// An initial value takes a folded comparison of texts or conversion with a text (E0313 before),
// a CHAR's and a WCHAR's the character's code: the values the VM computes for the same
// expressions at run time.
TEST(ConstantExpressionsOf, TextComparisonsAndConversionsAreInitialValues) {
    StProgram run(R"(
PROGRAM Main
VAR CONSTANT kName : STRING[3] := 'abcdef'; END_VAR
VAR
    less : BOOL := 'a' < 'b';
    same : BOOL := EQ(kName, 'abc', LEFT('abcd', 3));
    number : STRING := INT_TO_STRING(42);
    real : STRING[4] := LREAL_TO_STRING(1.0 / 3.0);
    time : STRING := TIME_TO_STRING(T#1m30s);
    parsed : INT := STRING_TO_INT('-17');
    ratio : REAL := STRING_TO_REAL('1.1');
    first : CHAR := STRING_TO_CHAR(kName);
    wide : WCHAR := WCHAR#"$20AC";
    text : WSTRING := STRING_TO_WSTRING('$E9t$E9');
    narrow : STRING := WSTRING_TO_STRING("a$20AC");
    largest : STRING := MAX('abc', kName, 'ab');
    less_now : BOOL; same_now : BOOL; number_now : STRING; real_now : STRING[4];
    time_now : STRING; parsed_now : INT; ratio_now : REAL; first_now : CHAR; wide_now : WCHAR;
    text_now : WSTRING; narrow_now : STRING; largest_now : STRING;
    a : STRING := 'a'; b : STRING := 'b'; forty_two : INT := 42; third : LREAL := 3.0;
    minute : TIME := T#1m30s; name : STRING[3] := 'abcdef'; euro : WSTRING := "$20AC";
END_VAR
less_now := a < b;
same_now := EQ(name, 'abc', LEFT('abcd', 3));
number_now := INT_TO_STRING(forty_two);
real_now := LREAL_TO_STRING(1.0 / third);
time_now := TIME_TO_STRING(minute);
parsed_now := STRING_TO_INT(CONCAT('-', '17'));
ratio_now := STRING_TO_REAL(CONCAT('1.', '1'));
first_now := STRING_TO_CHAR(name);
wide_now := WSTRING_TO_WCHAR(euro);
text_now := STRING_TO_WSTRING(CONCAT('$E9t', '$E9'));
narrow_now := WSTRING_TO_STRING(CONCAT("a", euro));
largest_now := MAX(a, name, 'ab');
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(run.get<std::uint8_t>("Main.less"), 1);
    EXPECT_EQ(run.get<std::uint8_t>("Main.same"), 1);
    EXPECT_EQ(run.get_string("Main.number"), "42");
    EXPECT_EQ(run.get_string("Main.real"), "0.33");
    EXPECT_EQ(run.get_string("Main.time"), "T#1m30s");
    EXPECT_EQ(run.get<std::int16_t>("Main.parsed"), -17);
    EXPECT_EQ(run.get<float>("Main.ratio"), 1.1F);
    EXPECT_EQ(run.get<std::uint8_t>("Main.first"), 'a');
    EXPECT_EQ(run.get<std::uint16_t>("Main.wide"), 0x20AC);
    EXPECT_TRUE(run.get_wstring("Main.text") == u"\u00E9t\u00E9");
    EXPECT_EQ(run.get_string("Main.narrow"), "a?");
    EXPECT_EQ(run.get_string("Main.largest"), "abc");
    ASSERT_TRUE(run.scans(1));
    for (const char* name : {"number", "real", "time", "narrow", "largest"}) {
        const std::string path = std::string("Main.") + name;
        EXPECT_EQ(run.get_string(path), run.get_string(path + "_now")) << name;
    }
    for (const char* name : {"less", "same", "first"}) {
        const std::string path = std::string("Main.") + name;
        EXPECT_EQ(run.get<std::uint8_t>(path), run.get<std::uint8_t>(path + "_now")) << name;
    }
    EXPECT_EQ(run.get<std::int16_t>("Main.parsed"), run.get<std::int16_t>("Main.parsed_now"));
    EXPECT_EQ(run.get<float>("Main.ratio"), run.get<float>("Main.ratio_now"));
    EXPECT_EQ(run.get<std::uint16_t>("Main.wide"), run.get<std::uint16_t>("Main.wide_now"));
    EXPECT_TRUE(run.get_wstring("Main.text") == run.get_wstring("Main.text_now"));
}

// A conversion's text is cut at the capacity of its type (STRING[80], WSTRING[80]) in an
// initial value as at run time, also where the variable is longer.
TEST(ConstantExpressionsOf, AConvertedTextIsCutAtItsTypesCapacityInAnInitialValue) {
    const std::string ninety(90, 'x');
    StProgram run(R"(
PROGRAM Main
VAR CONSTANT kLong : STRING[90] := ')" +
                  ninety + R"('; END_VAR
VAR
    wide : WSTRING[100] := STRING_TO_WSTRING(kLong);
    same : STRING[100] := TO_STRING(kLong);
    wide_now : WSTRING[100]; same_now : STRING[100]; long : STRING[90] := ')" +
                  ninety + R"(';
END_VAR
wide_now := STRING_TO_WSTRING(long);
same_now := TO_STRING(long);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_TRUE(run.get_wstring("Main.wide") == std::u16string(80, u'x'));
    EXPECT_EQ(run.get_string("Main.same"), std::string(80, 'x'));
    ASSERT_TRUE(run.scans(1));
    EXPECT_TRUE(run.get_wstring("Main.wide") == run.get_wstring("Main.wide_now"));
    EXPECT_EQ(run.get_string("Main.same"), run.get_string("Main.same_now"));
}

} // namespace
} // namespace eposp::compiler::test
