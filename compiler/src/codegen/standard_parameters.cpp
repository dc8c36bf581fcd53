// The input names of the standard functions (IEC 61131-3 ed. 3, tables 22-43): a formal call
// (`LIMIT(MN := 0, IN := v, MX := 10)`) may name its inputs in any order; code generation takes
// them in the order of the parameters.

#include "eposp/compiler/sema/symbol.hpp"
#include "pou_generator.hpp"

#include <array>
#include <charconv>
#include <fmt/format.h>

namespace eposp::compiler::codegen {
namespace {

struct NamedInputs {
    std::string_view function;
    std::array<std::string_view, 4> inputs; // empty names end the list
};

constexpr std::array kNamedInputs{
    NamedInputs{"SEL", {"G", "IN0", "IN1"}},
    NamedInputs{"LIMIT", {"MN", "IN", "MX"}},
    NamedInputs{"SHL", {"IN", "N"}},
    NamedInputs{"SHR", {"IN", "N"}},
    NamedInputs{"ROL", {"IN", "N"}},
    NamedInputs{"ROR", {"IN", "N"}},
    NamedInputs{"LEFT", {"IN", "L"}},
    NamedInputs{"RIGHT", {"IN", "L"}},
    NamedInputs{"MID", {"IN", "L", "P"}},
    NamedInputs{"DELETE", {"IN", "L", "P"}},
    NamedInputs{"INSERT", {"IN1", "IN2", "P"}},
    NamedInputs{"REPLACE", {"IN1", "IN2", "L", "P"}},
    NamedInputs{"ATAN2", {"Y", "X"}},
};

/// The numbered inputs of the extensible and two-input functions start at IN1 (MUX: K, then
/// IN0, IN1, ...); the others have one input, IN.
bool has_numbered_inputs(std::string_view function) {
    static constexpr std::array kNumbered{"ADD", "MUL", "SUB", "DIV",    "MOD", "EXPT", "AND",
                                          "OR",  "XOR", "MAX", "MIN",    "GT",  "GE",   "EQ",
                                          "LE",  "LT",  "NE",  "CONCAT", "FIND"};
    return std::find(kNumbered.begin(), kNumbered.end(), function) != kNumbered.end() ||
           is_time_function(function);
}

/// The number n of `parameter` = "IN<n>".
std::optional<std::size_t> input_number(std::string_view parameter) {
    std::size_t number = 0;
    const auto digits = parameter.substr(std::min<std::size_t>(2, parameter.size()));
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), number);
    if (!parameter.starts_with("IN") || digits.empty() || error != std::errc{} ||
        end != digits.data() + digits.size()) {
        return std::nullopt;
    }
    return number;
}

/// The 0-based position of input `parameter` (folded) of standard function `function`.
std::optional<std::size_t> input_position(std::string_view function, std::string_view parameter) {
    for (const NamedInputs& named : kNamedInputs) {
        if (named.function == function) {
            const auto at = std::find(named.inputs.begin(), named.inputs.end(), parameter);
            return at != named.inputs.end() && !parameter.empty()
                       ? std::optional(static_cast<std::size_t>(at - named.inputs.begin()))
                       : std::nullopt;
        }
    }
    if (function == "MUX") {
        const auto number = input_number(parameter);
        return parameter == "K" ? std::optional<std::size_t>(0)
               : number         ? std::optional(*number + 1)
                                : std::nullopt;
    }
    if (!has_numbered_inputs(function)) {
        return parameter == "IN" ? std::optional<std::size_t>(0) : std::nullopt;
    }
    const auto number = input_number(parameter);
    return number && *number >= 1 ? std::optional(*number - 1) : std::nullopt;
}

} // namespace

std::optional<Arguments> PouGenerator::in_parameter_order(const std::string& name,
                                                          const Arguments& arguments) {
    const bool formal = std::any_of(arguments.begin(), arguments.end(),
                                    [](const ast::Argument* a) { return a->name.has_value(); });
    if (!formal || name == "ADR" || name == "SIZEOF") {
        return arguments;
    }
    Arguments ordered(arguments.size(), nullptr);
    for (const ast::Argument* argument : arguments) {
        if (!argument->name) {
            program_.refused_by_checks(DiagnosticCode::E0415); // checks/call_forms.cpp
            return std::nullopt;
        }
        const auto position = input_position(name, sema::fold_case(argument->name->name));
        if (!position || *position >= ordered.size()) {
            error(DiagnosticCode::E0210, argument->range,
                  fmt::format("{} has no input '{}' here", name, argument->name->name));
            return std::nullopt;
        }
        if (ordered[*position] != nullptr) {
            program_.refused_by_checks(DiagnosticCode::E0414); // checks/repeated_parameters.cpp
            return std::nullopt;
        }
        ordered[*position] = argument;
    }
    return ordered;
}

} // namespace eposp::compiler::codegen
