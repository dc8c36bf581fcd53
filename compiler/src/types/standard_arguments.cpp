// The formal input names of the standard functions (IEC 61131-3 ed. 3, tables 22-36).

#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace eposp::compiler::types {

namespace {

const std::map<std::string, std::vector<std::string>, std::less<>> kFixed = {
    {"SEL", {"G", "IN0", "IN1"}},
    {"LIMIT", {"MN", "IN", "MX"}},
    {"ATAN2", {"Y", "X"}},
    {"SHL", {"IN", "N"}},
    {"SHR", {"IN", "N"}},
    {"ROL", {"IN", "N"}},
    {"ROR", {"IN", "N"}},
    {"LEFT", {"IN", "L"}},
    {"RIGHT", {"IN", "L"}},
    {"MID", {"IN", "L", "P"}},
    {"INSERT", {"IN1", "IN2", "P"}},
    {"DELETE", {"IN", "L", "P"}},
    {"REPLACE", {"IN1", "IN2", "L", "P"}},
    {"FIND", {"IN1", "IN2"}},
    {"LOWER_BOUND", {"ARR", "DIM"}},
    {"UPPER_BOUND", {"ARR", "DIM"}},
};

/// The position of the formal input `input` of `name`; nothing if it has no such input.
std::optional<std::size_t> position(std::string_view name, const std::string& input) {
    if (const auto fixed = kFixed.find(name); fixed != kFixed.end()) {
        const auto at = std::find(fixed->second.begin(), fixed->second.end(), input);
        if (at == fixed->second.end()) {
            return std::nullopt;
        }
        return static_cast<std::size_t>(at - fixed->second.begin());
    }
    if (input == "IN") {
        return 0;
    }
    if (name == "MUX" && input == "K") {
        return 0;
    }
    // Extensible inputs: IN1, IN2, ... (MUX: IN0, IN1, ... after K).
    if (input.size() > 2 && input.starts_with("IN") &&
        std::all_of(input.begin() + 2, input.end(),
                    [](unsigned char c) { return std::isdigit(c) != 0; })) {
        const std::size_t number = std::stoul(input.substr(2));
        if (name == "MUX") {
            return number + 1;
        }
        return number >= 1 ? std::optional<std::size_t>(number - 1) : std::nullopt;
    }
    return std::nullopt;
}

} // namespace

std::vector<const ast::Argument*> standard_arguments(std::string_view name,
                                                     const ast::CallExpression& call) {
    std::vector<const ast::Argument*> result;
    for (const ast::Argument& argument : call.arguments) {
        if (!argument.name) {
            result.push_back(&argument);
            continue;
        }
        const std::string input = sema::fold_case(argument.name->name);
        if (input == "EN" || input == "ENO") {
            continue;
        }
        const auto at = position(name, input);
        if (!at) {
            result.push_back(nullptr);
            continue;
        }
        if (result.size() <= *at) {
            result.resize(*at + 1, nullptr);
        }
        result[*at] = &argument;
    }
    return result;
}

} // namespace eposp::compiler::types
