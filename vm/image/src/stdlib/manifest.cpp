// The standard-library manifest (manifest.hpp): the rows of the function blocks (IEC 61131-3
// ed. 3, tables 43-46; those of the functions are manifest.hpp's, constant) and the bindings.

#include "eposp/vm/stdlib/manifest.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

namespace eposp::vm::stdlib {
namespace {

using F = Family;
using N = NativeNaming;
using T = NativeType;

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

constexpr StandardFunction kConversion = rows::one("TO", F::Truncate); // IN

} // namespace

std::span<const StandardFunction> standard_functions() {
    return rows::kFunctions;
}

const StandardFunction* find_standard_function(std::string_view name) {
    const auto found = std::find_if(rows::kFunctions.begin(), rows::kFunctions.end(),
                                    [&](const StandardFunction& row) { return row.name == name; });
    return found != rows::kFunctions.end() ? &*found : nullptr;
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

NativeBinding native_binding(NativeFunctionName name, Variant variant) {
    return native_binding(name.row(), variant);
}

std::vector<NativeBinding> standard_function_natives() {
    std::vector<NativeBinding> natives;
    for (const StandardFunction& function : rows::kFunctions) {
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
    const auto row =
        std::find_if(rows::kFunctions.begin(), rows::kFunctions.end(), [&](const auto& f) {
            return f.family == F::Comparison && f.operation == operation;
        });
    if (row == rows::kFunctions.end()) {
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
        for (const StandardFunction& function : rows::kFunctions) {
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
