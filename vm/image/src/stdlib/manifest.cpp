// The rows of the standard-library manifest (manifest.hpp): IEC 61131-3 ed. 3, tables 22-36
// (functions) and 43-46 (function blocks).

#include "eposp/vm/stdlib/manifest.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace eposp::vm::stdlib {
namespace {

using F = Family;
using N = NativeNaming;
using T = NativeType;
using Op = Operation;
constexpr std::uint8_t X = kExtensible;

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

constexpr std::array kFunctions{
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
    time("CONCAT_DATE_TOD", Op::Add, {T::Date, T::TimeOfDay, T::DateAndTime}),
};

constexpr StandardParameter in(std::string_view name, std::string_view type) {
    return {name, false, type};
}
constexpr StandardParameter out(std::string_view name, std::string_view type) {
    return {name, true, type};
}

// Tables 43-46: bistables, edge detection, counters, timers; all ST.
constexpr std::array kFunctionBlocks{
    StandardFunctionBlock{"SR", {in("S1", "BOOL"), in("R", "BOOL"), out("Q1", "BOOL")}},
    StandardFunctionBlock{"RS", {in("S", "BOOL"), in("R1", "BOOL"), out("Q1", "BOOL")}},
    StandardFunctionBlock{"R_TRIG", {in("CLK", "BOOL"), out("Q", "BOOL")}},
    StandardFunctionBlock{"F_TRIG", {in("CLK", "BOOL"), out("Q", "BOOL")}},
    StandardFunctionBlock{
        "CTU",
        {in("CU", "BOOL"), in("R", "BOOL"), in("PV", "INT"), out("Q", "BOOL"), out("CV", "INT")},
        true},
    StandardFunctionBlock{
        "CTD",
        {in("CD", "BOOL"), in("LD", "BOOL"), in("PV", "INT"), out("Q", "BOOL"), out("CV", "INT")},
        true},
    StandardFunctionBlock{"CTUD",
                          {in("CU", "BOOL"), in("CD", "BOOL"), in("R", "BOOL"), in("LD", "BOOL"),
                           in("PV", "INT"), out("QU", "BOOL"), out("QD", "BOOL"), out("CV", "INT")},
                          true},
    StandardFunctionBlock{"RTC",
                          {in("IN", "BOOL"), in("PDT", "DT"), out("Q", "BOOL"), out("CDT", "DT")}},
    StandardFunctionBlock{
        "TP", {in("IN", "BOOL"), in("PT", "TIME"), out("Q", "BOOL"), out("ET", "TIME")}},
    StandardFunctionBlock{
        "TON", {in("IN", "BOOL"), in("PT", "TIME"), out("Q", "BOOL"), out("ET", "TIME")}},
    StandardFunctionBlock{
        "TOF", {in("IN", "BOOL"), in("PT", "TIME"), out("Q", "BOOL"), out("ET", "TIME")}},
};

/// The number n of `input` = "IN<n>".
std::optional<std::size_t> input_number(std::string_view input) {
    if (!input.starts_with("IN") || input.size() == 2) {
        return std::nullopt;
    }
    std::size_t number = 0;
    const auto digits = input.substr(2);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), number);
    if (error != std::errc{} || end != digits.data() + digits.size()) {
        return std::nullopt;
    }
    return number;
}

constexpr StandardFunction kConversion = one("TO", F::Truncate); // IN

} // namespace

std::span<const StandardFunction> standard_functions() {
    return kFunctions;
}

const StandardFunction* find_standard_function(std::string_view name) {
    const auto found = std::find_if(kFunctions.begin(), kFunctions.end(),
                                    [&](const StandardFunction& row) { return row.name == name; });
    return found != kFunctions.end() ? &*found : nullptr;
}

std::optional<std::size_t> input_position(const StandardFunction* function,
                                          std::string_view input) {
    const StandardFunction& row = function != nullptr ? *function : kConversion;
    const auto end = std::find(row.inputs.begin(), row.inputs.end(), std::string_view{});
    const auto at = std::find(row.inputs.begin(), end, input);
    if (at != end && !input.empty()) {
        return static_cast<std::size_t>(at - row.inputs.begin());
    }
    const auto number = input_number(input);
    if (!row.numbered_from || !number || *number < *row.numbered_from) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(end - row.inputs.begin()) + *number - *row.numbered_from;
}

NativeBinding native_binding(const StandardFunction& function, Variant variant) {
    using S = Scalar;
    const bool wide = variant == Variant::Wide;
    NativeBinding binding{std::string(function.name), {}};
    switch (function.naming) {
    case N::None:
        throw std::logic_error("no native for " + binding.name);
    case N::RealWidth: {
        const S real = wide ? S::F64 : S::F32;
        binding.name += wide ? "_LREAL" : "_REAL";
        binding.signature = {true, real, std::vector<S>(function.max_inputs, real)};
        break;
    }
    case N::CharWidth: {
        if (wide) {
            binding.name += "_WSTRING";
        }
        // CONCAT is binary in the VM: the caller folds its inputs left to right.
        const std::size_t texts = function.max_inputs == kExtensible ? 2 : function.texts;
        const std::size_t numbers = function.max_inputs == kExtensible
                                        ? 0
                                        : std::size_t{function.max_inputs} - function.texts;
        if (function.text_result == TextResult::Count) {
            binding.signature = {true, S::I32, std::vector<S>(texts, S::Ptr)};
            break;
        }
        std::vector<S> parameters(texts + 1, S::Ptr); // the result first
        parameters.insert(parameters.end(), numbers, S::I32);
        binding.signature = {false, S::Bool, std::move(parameters)};
        break;
    }
    case N::Plain:
        binding.signature = {true, S::I64, {S::I64, S::I64}};
        break;
    case N::Factor:
        if (wide) {
            binding.name += "_LREAL";
        }
        binding.signature = {true, S::I64, {S::I64, wide ? S::F64 : S::I64}};
        break;
    }
    return binding;
}

NativeBinding native_binding(std::string_view name, Variant variant) {
    const StandardFunction* function = find_standard_function(name);
    if (function == nullptr) {
        throw std::logic_error("no standard function " + std::string(name));
    }
    return native_binding(*function, variant);
}

std::vector<NativeBinding> standard_function_natives() {
    std::vector<NativeBinding> natives;
    for (const StandardFunction& function : kFunctions) {
        if (function.naming == N::None) {
            continue;
        }
        natives.push_back(native_binding(function, Variant::Base));
        if (function.naming != N::Plain) {
            natives.push_back(native_binding(function, Variant::Wide));
        }
    }
    return natives;
}

namespace {

/// A type's name in the natives' names: TOD and DT short, as CODESYS names their conversions.
std::string conversion_name(NativeType type) {
    switch (type) {
    case T::TimeOfDay:
        return "TOD";
    case T::DateAndTime:
        return "DT";
    case T::Ltod:
        return "LTIME_OF_DAY";
    case T::Ldt:
        return "LDATE_AND_TIME";
    default:
        return std::string(native_type_name(type));
    }
}

std::string text_name(CharWidth width) {
    return width == CharWidth::Wide ? "WSTRING" : "STRING";
}

} // namespace

NativeBinding to_text_binding(NativeType from, CharWidth width) {
    return {conversion_name(from) + "_TO_" + text_name(width),
            {false, Scalar::Bool, {Scalar::Ptr, native_scalar(from)}}};
}

NativeBinding from_text_binding(NativeType to, CharWidth width) {
    return {text_name(width) + "_TO_" + conversion_name(to),
            {true, native_scalar(to), {Scalar::Ptr}}};
}

NativeBinding text_width_binding(CharWidth to) {
    const CharWidth from = to == CharWidth::Wide ? CharWidth::Narrow : CharWidth::Wide;
    return {text_name(from) + "_TO_" + text_name(to),
            {false, Scalar::Bool, {Scalar::Ptr, Scalar::Ptr}}};
}

NativeBinding date_time_part_binding(NativeType part) {
    return {"DT_TO_" + conversion_name(part), {true, Scalar::I64, {Scalar::I64}}};
}

NativeBinding text_assignment_binding(CharWidth width) {
    return {"ASSIGN_" + text_name(width), {false, Scalar::Bool, {Scalar::Ptr, Scalar::Ptr}}};
}

NativeBinding text_comparison_binding(Operation operation, CharWidth width) {
    const auto row = std::find_if(kFunctions.begin(), kFunctions.end(), [&](const auto& f) {
        return f.family == F::Comparison && f.operation == operation;
    });
    if (row == kFunctions.end()) {
        throw std::logic_error("no comparison for the operation");
    }
    return {std::string(row->name) + "_" + text_name(width),
            {true, Scalar::Bool, {Scalar::Ptr, Scalar::Ptr}}};
}

NativeBinding clock_binding() {
    return {"CURRENT_TIME", {true, native_scalar(T::Time), {}}};
}

std::vector<NativeBinding> helper_natives() {
    std::vector<NativeBinding> natives;
    for (const CharWidth width : {CharWidth::Narrow, CharWidth::Wide}) {
        natives.push_back(text_assignment_binding(width));
        for (const StandardFunction& function : kFunctions) {
            if (function.family == F::Comparison) {
                natives.push_back(text_comparison_binding(function.operation, width));
            }
        }
    }
    natives.push_back(clock_binding());
    return natives;
}

std::span<const StandardFunctionBlock> standard_function_blocks() {
    return kFunctionBlocks;
}

std::string_view StandardBlockVariant::type_of(const StandardParameter& parameter) const {
    return block->counter && parameter.type == "INT" ? counter_type : parameter.type;
}

std::vector<StandardBlockVariant> standard_block_variants() {
    std::vector<StandardBlockVariant> variants;
    for (const StandardFunctionBlock& block : kFunctionBlocks) {
        variants.push_back({std::string(block.name), &block, "INT"});
    }
    for (const std::string_view type : kCounterTypes) {
        for (const StandardFunctionBlock& block : kFunctionBlocks) {
            if (block.counter) {
                variants.push_back(
                    {std::string(block.name) + "_" + std::string(type), &block, type});
            }
        }
    }
    return variants;
}

} // namespace eposp::vm::stdlib
