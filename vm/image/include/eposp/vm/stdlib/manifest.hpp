#pragma once

// The standard-library manifest: every standard function and function block of IEC 61131-3
// ed. 3 (6.6.2.5, 6.6.3.5) described once, one row each: its formal inputs, its overload family
// (which the typing stage turns into a type rule), how many inputs it takes, how it is
// implemented (opcodes at the call, a native of the VM, or ST in the compiler's built-in
// library) and, for a native, the VM binding: the native's name and signature. Name resolution,
// typing, code generation and the VM's registration all read these rows; none keeps its own
// list. It lives in vm_image because both the compiler (which links only vm_image) and the
// runtime read it.

#include "eposp/vm/image.hpp"
#include "eposp/vm/native_type.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::vm::stdlib {

/// The overload family of a standard function: the type rule of ed. 3, tables 22-36, that the
/// typing stage applies and the emitter that code generation picks.
enum class Family : std::uint8_t {
    Real,       ///< ANY_REAL -> the same (an integer input is taken as LREAL): SQRT, SIN, ATAN2…
    Power,      ///< IN1: ANY_REAL, IN2: ANY_NUM -> IN1's type: EXPT
    Absolute,   ///< ANY_NUM -> the same: ABS
    Move,       ///< ANY -> the same: MOVE
    Arithmetic, ///< ANY_NUM (or ANY_BIT) inputs of one type -> it: ADD, MUL, SUB, DIV, MOD
    Logic,      ///< ANY_BIT (or BOOL) inputs of one type -> it: AND, OR, XOR, NOT
    Comparison, ///< inputs of one type -> BOOL, each neighbouring pair compared: GT, EQ…
    Shift,      ///< IN: ANY_BIT, N: ANY_INT -> IN's type: SHL, SHR, ROL, ROR
    Select,     ///< G: BOOL, IN0, IN1 of one type -> it: SEL
    Extreme,    ///< inputs of one type -> it: MAX, MIN
    Limit,      ///< MN, IN, MX of one type -> it: LIMIT
    Multiplex,  ///< K: ANY_INT, IN0… of one type -> it: MUX
    Text,       ///< texts (STRING or WSTRING alike), then ANY_INT lengths and positions: LEN…
    Bound,      ///< an array and a constant dimension -> DINT: LOWER_BOUND, UPPER_BOUND
    Time,       ///< table 30: operands of fixed time types (TimeRule): ADD_TIME, SUB_DT_DT…
    Address,    ///< ADR: the address of a variable, for any POINTER TO
    Size,       ///< SIZEOF: a constant of the smallest unsigned type holding the size
    Truncate,   ///< TRUNC: ANY_REAL -> DINT (typed as a conversion)
};

/// How a standard function or FB is implemented.
enum class Implementation : std::uint8_t {
    Inline, ///< opcodes at the call site
    Native, ///< a CallNative of the VM's standard library (native_binding)
    St,     ///< ST in the compiler's built-in library (stdlib/standard_library_source.cpp)
};

/// How a native standard function's variants are named, one per argument type.
enum class NativeNaming : std::uint8_t {
    None,      ///< no native
    Plain,     ///< one native of the function's name: ADD_TOD_TIME
    RealWidth, ///< NAME_REAL and NAME_LREAL
    CharWidth, ///< NAME on STRING, NAME_WSTRING on WSTRING
    Factor,    ///< NAME by an integer (LINT), NAME_LREAL by a real
};

/// Which variant of a native: a REAL, a STRING, an integer factor (Base) or an LREAL, a WSTRING,
/// a real factor (Wide).
enum class Variant : std::uint8_t { Base, Wide };

/// The string functions' result (table 36).
enum class TextResult : std::uint8_t {
    Count,   ///< an INT: LEN, FIND
    Largest, ///< a text of the largest input capacity: LEFT, RIGHT, MID, DELETE
    Sum,     ///< a text of the sum of the input capacities: CONCAT, INSERT, REPLACE
};

/// The capacity of a text function's result after one more text input of `capacity`, from
/// the result's capacity `so_far` (0 before the first): what the inputs can make, at most a
/// STRING's largest.
constexpr std::uint32_t text_capacity(TextResult rule, std::uint32_t so_far,
                                      std::uint32_t capacity) {
    const std::uint32_t next = rule == TextResult::Sum ? so_far + capacity
                               : capacity > so_far     ? capacity
                                                       : so_far;
    return next < kMaxStringCapacity ? next : kMaxStringCapacity;
}

/// What an arithmetic, logic, comparison, shift, MAX/MIN or time function computes, as the
/// operator or opcode of the same name does.
enum class Operation : std::uint8_t {
    None,
    Add,
    Subtract,
    Multiply,
    Divide,
    Modulo,
    And,
    Or,
    Xor,
    Not,
    Greater,
    GreaterEqual,
    Equal,
    LessEqual,
    Less,
    NotEqual,
    ShiftLeft,
    ShiftRight,
    RotateLeft,
    RotateRight,
    Maximum,
    Minimum,
};

/// A table 30 function's operand and result types; `scaled`: the second operand is any number
/// (MUL_TIME, DIV_TIME) rather than `second`; `overloaded`: ADD, SUB, MUL, DIV and their
/// operators take this row on its types (table 30's note; CONCAT_DATE_TOD has no symbol).
struct TimeRule {
    NativeType first = NativeType::Time;
    NativeType second = NativeType::Time;
    NativeType result = NativeType::Time;
    bool scaled = false;
    bool overloaded = true;
};

/// An extensible function takes at most this many inputs.
inline constexpr std::uint8_t kExtensible = 64;

struct StandardFunction {
    std::string_view name;
    Family family;
    /// The formal inputs before the numbered ones, in the order of the signature.
    std::array<std::string_view, 4> inputs{};
    /// The number of the first numbered input (`IN1` of ADD, `IN0` of MUX), if any follow.
    std::optional<std::uint8_t> numbered_from{};
    std::uint8_t min_inputs = 1;
    std::uint8_t max_inputs = 1;
    Operation operation = Operation::None;
    /// How its natives are named; None: it is Implementation::Inline.
    NativeNaming naming = NativeNaming::None;
    /// Text: how many inputs are texts (the rest are ANY_INT), and the result's rule.
    std::uint8_t texts = 0;
    TextResult text_result = TextResult::Count;
    /// Time: the operand and result types.
    TimeRule time{};
};

/// A standard function is a native of the VM or opcodes at the call.
constexpr Implementation implementation(const StandardFunction& function) {
    return function.naming == NativeNaming::None ? Implementation::Inline : Implementation::Native;
}

/// The rows of the standard functions: IEC 61131-3 ed. 3, tables 22-36.
namespace rows {

using F = Family;
using N = NativeNaming;
using T = NativeType;
using Op = Operation;
inline constexpr std::uint8_t X = kExtensible;

constexpr StandardFunction one(std::string_view name, Family family,
                               NativeNaming naming = N::None) {
    return {.name = name, .family = family, .inputs = {"IN"}, .naming = naming};
}

/// IN1, IN2, … from `min` to `max` inputs.
constexpr StandardFunction numbered(std::string_view name, Family family, std::uint8_t min,
                                    std::uint8_t max, Operation operation = Op::None) {
    return {.name = name,
            .family = family,
            .numbered_from = 1,
            .min_inputs = min,
            .max_inputs = max,
            .operation = operation};
}

constexpr StandardFunction fixed(std::string_view name, Family family,
                                 std::array<std::string_view, 4> inputs, std::uint8_t count,
                                 Operation operation = Op::None) {
    return {.name = name,
            .family = family,
            .inputs = inputs,
            .min_inputs = count,
            .max_inputs = count,
            .operation = operation};
}

constexpr StandardFunction real2(StandardFunction row) {
    row.naming = N::RealWidth;
    return row;
}

constexpr StandardFunction text(StandardFunction row, std::uint8_t texts, TextResult result) {
    row.naming = N::CharWidth;
    row.texts = texts;
    row.text_result = result;
    return row;
}

/// A table 30 function: IN1, IN2; a native where one add is not all it does.
constexpr StandardFunction time(std::string_view name, Operation operation, TimeRule rule,
                                NativeNaming naming = N::None) {
    StandardFunction row = numbered(name, F::Time, 2, 2, operation);
    row.time = rule;
    row.naming = naming;
    return row;
}

/// Every standard function's row (standard_functions()), constant so that a row named in code is
/// found when it is compiled (NativeFunctionName).
inline constexpr std::array kFunctions{
    // Table 23-24 (numeric): SQRT is an opcode, the others natives per real type.
    one("ABS", F::Absolute),
    one("SQRT", F::Real),
    one("LN", F::Real, N::RealWidth),
    one("LOG", F::Real, N::RealWidth),
    one("EXP", F::Real, N::RealWidth),
    one("SIN", F::Real, N::RealWidth),
    one("COS", F::Real, N::RealWidth),
    one("TAN", F::Real, N::RealWidth),
    one("ASIN", F::Real, N::RealWidth),
    one("ACOS", F::Real, N::RealWidth),
    one("ATAN", F::Real, N::RealWidth),
    real2(fixed("ATAN2", F::Real, {"Y", "X"}, 2)),
    real2(numbered("EXPT", F::Power, 2, 2)),
    // Table 24 (arithmetic): ADD and MUL extensible.
    numbered("ADD", F::Arithmetic, 2, X, Op::Add),
    numbered("MUL", F::Arithmetic, 2, X, Op::Multiply),
    numbered("SUB", F::Arithmetic, 2, 2, Op::Subtract),
    numbered("DIV", F::Arithmetic, 2, 2, Op::Divide),
    numbered("MOD", F::Arithmetic, 2, 2, Op::Modulo),
    one("MOVE", F::Move),
    // Tables 26-27 (bit shift, bitwise).
    fixed("SHL", F::Shift, {"IN", "N"}, 2, Op::ShiftLeft),
    fixed("SHR", F::Shift, {"IN", "N"}, 2, Op::ShiftRight),
    fixed("ROL", F::Shift, {"IN", "N"}, 2, Op::RotateLeft),
    fixed("ROR", F::Shift, {"IN", "N"}, 2, Op::RotateRight),
    numbered("AND", F::Logic, 2, X, Op::And),
    numbered("OR", F::Logic, 2, X, Op::Or),
    numbered("XOR", F::Logic, 2, X, Op::Xor),
    StandardFunction{.name = "NOT", .family = F::Logic, .inputs = {"IN"}, .operation = Op::Not},
    // Table 28 (selection).
    fixed("SEL", F::Select, {"G", "IN0", "IN1"}, 3),
    numbered("MAX", F::Extreme, 2, X, Op::Maximum),
    numbered("MIN", F::Extreme, 2, X, Op::Minimum),
    fixed("LIMIT", F::Limit, {"MN", "IN", "MX"}, 3),
    StandardFunction{.name = "MUX",
                     .family = F::Multiplex,
                     .inputs = {"K"},
                     .numbered_from = 0,
                     .min_inputs = 3,
                     .max_inputs = X},
    // Table 29 (comparison).
    numbered("GT", F::Comparison, 2, X, Op::Greater),
    numbered("GE", F::Comparison, 2, X, Op::GreaterEqual),
    numbered("EQ", F::Comparison, 2, X, Op::Equal),
    numbered("LE", F::Comparison, 2, X, Op::LessEqual),
    numbered("LT", F::Comparison, 2, X, Op::Less),
    numbered("NE", F::Comparison, 2, X, Op::NotEqual),
    // Table 36 (character strings): texts first, then lengths and positions.
    text(one("LEN", F::Text), 1, TextResult::Count),
    text(fixed("LEFT", F::Text, {"IN", "L"}, 2), 1, TextResult::Largest),
    text(fixed("RIGHT", F::Text, {"IN", "L"}, 2), 1, TextResult::Largest),
    text(fixed("MID", F::Text, {"IN", "L", "P"}, 3), 1, TextResult::Largest),
    text(numbered("CONCAT", F::Text, 2, X), X, TextResult::Sum),
    text(fixed("INSERT", F::Text, {"IN1", "IN2", "P"}, 3), 2, TextResult::Sum),
    text(fixed("DELETE", F::Text, {"IN", "L", "P"}, 3), 1, TextResult::Largest),
    text(fixed("REPLACE", F::Text, {"IN1", "IN2", "L", "P"}, 4), 2, TextResult::Sum),
    text(numbered("FIND", F::Text, 2, 2), 2, TextResult::Count),
    // Table 22 (TRUNC) and the CODESYS pointer functions.
    one("TRUNC", F::Truncate),
    one("ADR", F::Address),
    one("SIZEOF", F::Size),
    // 6.5.3: the bounds of an array; positional only (code generation reads them in order).
    StandardFunction{.name = "LOWER_BOUND", .family = F::Bound, .min_inputs = 2, .max_inputs = 2},
    StandardFunction{.name = "UPPER_BOUND", .family = F::Bound, .min_inputs = 2, .max_inputs = 2},
    // Table 30: all nanoseconds; TOD wraps around midnight (a native), a TIME scaled by a
    // number is a native per factor type.
    time("ADD_TIME", Op::Add, {T::Time, T::Time, T::Time}),
    time("ADD_TOD_TIME", Op::Add, {T::TimeOfDay, T::Time, T::TimeOfDay}, N::Plain),
    time("ADD_DT_TIME", Op::Add, {T::DateAndTime, T::Time, T::DateAndTime}),
    time("SUB_TIME", Op::Subtract, {T::Time, T::Time, T::Time}),
    time("SUB_DATE_DATE", Op::Subtract, {T::Date, T::Date, T::Time}),
    time("SUB_TOD_TIME", Op::Subtract, {T::TimeOfDay, T::Time, T::TimeOfDay}, N::Plain),
    time("SUB_TOD_TOD", Op::Subtract, {T::TimeOfDay, T::TimeOfDay, T::Time}),
    time("SUB_DT_TIME", Op::Subtract, {T::DateAndTime, T::Time, T::DateAndTime}),
    time("SUB_DT_DT", Op::Subtract, {T::DateAndTime, T::DateAndTime, T::Time}),
    time("MUL_TIME", Op::Multiply, {T::Time, T::Time, T::Time, true}, N::Factor),
    time("DIV_TIME", Op::Divide, {T::Time, T::Time, T::Time, true}, N::Factor),
    // DATE and TOD are nanoseconds since 1970 and since midnight: their sum is the DT.
    time("CONCAT_DATE_TOD", Op::Add, {T::Date, T::TimeOfDay, T::DateAndTime, false, false}),
    // The long forms, after the short ones so that the overloaded forms take the short row where
    // both fit (types::ExpressionTyper::time_row). Every time is nanoseconds in 64 bits, so they
    // compute as their short rows do, a long TOD with the TOD's native too (no native of theirs).
    time("ADD_LTIME", Op::Add, {T::Ltime, T::Ltime, T::Ltime}),
    time("ADD_LTOD_LTIME", Op::Add, {T::Ltod, T::Ltime, T::Ltod}),
    time("ADD_LDT_LTIME", Op::Add, {T::Ldt, T::Ltime, T::Ldt}),
    time("SUB_LTIME", Op::Subtract, {T::Ltime, T::Ltime, T::Ltime}),
    time("SUB_LDATE_LDATE", Op::Subtract, {T::Ldate, T::Ldate, T::Ltime}),
    time("SUB_LTOD_LTIME", Op::Subtract, {T::Ltod, T::Ltime, T::Ltod}),
    time("SUB_LTOD_LTOD", Op::Subtract, {T::Ltod, T::Ltod, T::Ltime}),
    time("SUB_LDT_LTIME", Op::Subtract, {T::Ldt, T::Ltime, T::Ldt}),
    time("SUB_LDT_LDT", Op::Subtract, {T::Ldt, T::Ldt, T::Ltime}),
    time("MUL_LTIME", Op::Multiply, {T::Ltime, T::Ltime, T::Ltime, true}),
    time("DIV_LTIME", Op::Divide, {T::Ltime, T::Ltime, T::Ltime, true}),
    // Ed. 3's long form of CONCAT_DATE_TOD: a DATE and an LTOD make an LDT.
    time("CONCAT_DATE_LTOD", Op::Add, {T::Date, T::Ltod, T::Ldt, false, false}),
};

} // namespace rows

/// The name of a standard function that has a native, checked when compiled: a string literal
/// that names no row, or a row without a native (`native_binding("MUL_TIM")`,
/// `native_binding("ADD")`), is no constant expression, so the program does not compile. A name
/// known only at run time goes through find_standard_function.
class NativeFunctionName {
public:
    // NOLINTNEXTLINE(google-explicit-constructor): a literal stands for its row at the call.
    consteval NativeFunctionName(const char* name) : row_(find(name)) {}

    constexpr const StandardFunction& row() const { return *row_; }

private:
    static consteval const StandardFunction* find(std::string_view name) {
        for (const StandardFunction& row : rows::kFunctions) {
            if (row.name == name && row.naming != NativeNaming::None) {
                return &row;
            }
        }
        no_standard_function_with_a_native_of_this_name();
        return nullptr;
    }
    /// Not constexpr, never defined: reaching it in find() is the compile-time error.
    static void no_standard_function_with_a_native_of_this_name();

    const StandardFunction* row_;
};

/// Every standard function (not the conversions `*_TO_*`, which are too many to list and follow
/// one rule: is_conversion in the compiler, one input IN).
std::span<const StandardFunction> standard_functions();
/// The row of the standard function `name` (upper case), if it is one.
const StandardFunction* find_standard_function(std::string_view name);

/// The 0-based position in the signature of the formal input `input` (upper case) of
/// `function`; nothing if it has no such input. A type conversion (`function` null) has IN.
std::optional<std::size_t> input_position(const StandardFunction* function, std::string_view input);

/// A native of the VM's standard library: its name and signature.
struct NativeBinding {
    std::string name;
    NativeSignature signature;
};

/// The native that implements `function` for `variant`: CONCAT is binary (folded left to right
/// by the caller); a text function writes its text result through its first parameter.
NativeBinding native_binding(const StandardFunction& function, Variant variant = Variant::Base);
/// The binding of the native of the function named `name`.
NativeBinding native_binding(NativeFunctionName name, Variant variant = Variant::Base);
/// Every native binding of every row, all variants: what the VM's standard library registers
/// for the standard functions.
std::vector<NativeBinding> standard_function_natives();

/// The natives of the type conversions that are no opcode (table 22), named after the types
/// (TOD, DT for the times of day and dates and times): `<type>_TO_STRING(dst, value)`,
/// `<type>_TO_WSTRING` of WCHAR; `STRING_TO_<type>(text)`, `WSTRING_TO_WCHAR`.
NativeBinding to_text_binding(NativeType from, CharWidth width);
NativeBinding from_text_binding(NativeType to, CharWidth width);
/// `STRING_TO_WSTRING(dst, text)` (to Wide) and `WSTRING_TO_STRING` (to Narrow).
NativeBinding text_width_binding(CharWidth to);
/// `DT_TO_DATE` and `DT_TO_TOD`: the date or the time of day of a DT.
NativeBinding date_time_part_binding(NativeType part);

// The runtime helpers: natives code generation calls for what is no call of a standard function
// (an assignment or comparison of texts, the standard timers' clock). Each is described here
// once; code generation calls it and the VM registers it by this binding.

/// `ASSIGN_STRING(dst, src)`, `ASSIGN_WSTRING`: `dst := src` between texts of different
/// capacities (the source cut to the destination's).
NativeBinding text_assignment_binding(CharWidth width);
/// `EQ_STRING(a, b)`, `LT_WSTRING`…: the comparison row of `operation` (Greater … NotEqual) on
/// two texts -> BOOL.
NativeBinding text_comparison_binding(Operation operation, CharWidth width);
/// `CURRENT_TIME()` -> TIME, nanoseconds of a monotonic clock: what the timers of the standard
/// library (TP, TON, TOF, RTC; IEC 61131-3 ed. 3, 6.6.3.5.5) read. The host supplies it
/// (vm::stdlib::register_clock), so a simulated run reads the event loop's virtual time.
NativeBinding clock_binding();
/// Every runtime helper's binding, each width of a text helper.
std::vector<NativeBinding> helper_natives();

struct StandardParameter {
    std::string_view name;
    bool output = false;
    std::string_view type;
};

struct StandardFunctionBlock {
    std::string_view name;
    std::array<StandardParameter, 8> parameters{}; ///< an empty name ends the list
    /// A counter of table 45 (PV and CV of type INT), which also comes as CTU_DINT, CTU_LINT,
    /// CTU_UDINT and CTU_ULINT with PV and CV of that type (kCounterTypes).
    bool counter = false;
    Implementation implementation = Implementation::St;
};

/// The types of the typed counters besides INT, in the order of the suffixes.
inline constexpr std::array<std::string_view, 4> kCounterTypes{"DINT", "LINT", "UDINT", "ULINT"};

/// Every standard function block (tables 43-46), the typed counters as their INT row.
std::span<const StandardFunctionBlock> standard_function_blocks();

/// A standard FB as programs name it: a row, or a typed counter of a counter row (CTU_DINT).
struct StandardBlockVariant {
    std::string name;
    const StandardFunctionBlock* block = nullptr;
    /// What the row's INT parameters (PV, CV) are: INT, or the typed counter's type.
    std::string_view counter_type;
    /// The type of `parameter`, a parameter of `block`, in this variant.
    std::string_view type_of(const StandardParameter& parameter) const;
};

/// Every standard FB by the name programs call it: the rows (the counters on INT), then the
/// typed counters of each of kCounterTypes in turn.
std::vector<StandardBlockVariant> standard_block_variants();

} // namespace eposp::vm::stdlib
