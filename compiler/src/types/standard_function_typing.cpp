// The standard functions of IEC 61131-3 ed. 3, tables 22-36, typed by their ANY_* signatures.

#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <set>

namespace eposp::compiler::types {

namespace {

const std::set<std::string> kReal1 = {"SQRT", "LN",  "LOG",  "EXP",  "SIN",
                                      "COS",  "TAN", "ASIN", "ACOS", "ATAN"};
const std::set<std::string> kArithmetic = {"ADD", "MUL", "SUB", "DIV", "MOD"};
const std::set<std::string> kComparison = {"GT", "GE", "EQ", "LE", "LT", "NE"};
const std::set<std::string> kBitwise = {"AND", "OR", "XOR"};
const std::set<std::string> kShift = {"SHL", "SHR", "ROL", "ROR"};

/// A time function's first input and second input (none: any number).
std::optional<std::pair<ast::ElementaryType, std::optional<ast::ElementaryType>>>
time_function(const std::string& name) {
    using E = ast::ElementaryType;
    static const std::map<std::string, std::pair<E, std::optional<E>>> functions = {
        {"ADD_TIME", {E::Time, E::Time}},
        {"SUB_TIME", {E::Time, E::Time}},
        {"MUL_TIME", {E::Time, std::nullopt}},
        {"DIV_TIME", {E::Time, std::nullopt}},
        {"ADD_TOD_TIME", {E::TimeOfDay, E::Time}},
        {"SUB_TOD_TIME", {E::TimeOfDay, E::Time}},
        {"ADD_DT_TIME", {E::DateAndTime, E::Time}},
        {"SUB_DT_TIME", {E::DateAndTime, E::Time}},
        {"SUB_DATE_DATE", {E::Date, E::Date}},
        {"SUB_TOD_TOD", {E::TimeOfDay, E::TimeOfDay}},
        {"SUB_DT_DT", {E::DateAndTime, E::DateAndTime}},
        {"CONCAT_DATE_TOD", {E::Date, E::TimeOfDay}},
    };
    const auto found = functions.find(name);
    if (found == functions.end()) {
        return std::nullopt;
    }
    return found->second;
}

ast::ElementaryType time_result(const std::string& name) {
    using E = ast::ElementaryType;
    if (name == "CONCAT_DATE_TOD" || name == "ADD_DT_TIME" || name == "SUB_DT_TIME") {
        return E::DateAndTime;
    }
    if (name == "ADD_TOD_TIME" || name == "SUB_TOD_TIME") {
        return E::TimeOfDay;
    }
    return E::Time;
}

} // namespace

const sema::Type* ExpressionTyper::standard_call(const ast::Expression& expression,
                                                 const ast::CallExpression& node,
                                                 const std::string& name,
                                                 const sema::Type* expected) {
    inputs(node); // EN and ENO
    std::vector<const ast::Expression*> values;
    const auto arguments = standard_arguments(name, node);
    for (const ast::Argument& argument : node.arguments) {
        // An input that names no input of this function, or one past those given.
        if (argument.name &&
            std::find(arguments.begin(), arguments.end(), &argument) == arguments.end()) {
            const std::string input = sema::fold_case(argument.name->name);
            const auto same = [&](const ast::Argument& other) {
                return &other != &argument && other.name &&
                       sema::fold_case(other.name->name) == input;
            };
            if (std::any_of(node.arguments.begin(), node.arguments.end(), same)) {
                return nullptr; // an input given twice: the checking stage's (E0414)
            }
            if (input != "EN" && input != "ENO") {
                return fail(DiagnosticCode::E0210, argument.range,
                            fmt::format("{} has no input '{}' here", name, argument.name->name));
            }
        }
    }
    for (const ast::Argument* argument : arguments) {
        if (argument == nullptr) {
            // A gap: an input named twice (the checking stage's E0414) or one past the others.
            const auto named = std::find_if(arguments.rbegin(), arguments.rend(),
                                            [](const ast::Argument* a) { return a; });
            if (named != arguments.rend()) {
                return fail(DiagnosticCode::E0210, (*named)->range,
                            fmt::format("{} has no input '{}' here", name,
                                        (*named)->name ? (*named)->name->name : "?"));
            }
            return nullptr;
        }
        values.push_back(argument->value.get());
    }
    const SourceRange& range = expression.range;
    const auto count = [&](std::size_t low, std::size_t high) {
        if (values.size() < low || values.size() > high) {
            diagnostics_.error(DiagnosticCode::E0306, range,
                               fmt::format("{} takes {} inputs, not {}", name, low, values.size()));
            return false;
        }
        return true;
    };
    const auto integer = [&](const ast::Expression& value) {
        const sema::Type* type = this->type(value, &elementary(E::Dint));
        if (type != nullptr && !sema::is_integer(program_.types().unranged(*type))) {
            diagnostics_.error(DiagnosticCode::E0305, value.range,
                               fmt::format("{} needs an integer here, not {}", name, type->name));
        }
    };
    const auto string = [&](const ast::Expression& value) {
        const sema::Type* type = this->type(value, nullptr);
        if (type != nullptr && type->kind != sema::TypeKind::String) {
            diagnostics_.error(
                DiagnosticCode::E0305, value.range,
                fmt::format("{} needs a STRING or WSTRING here, not {}", name, type->name));
            return static_cast<const sema::Type*>(nullptr);
        }
        return type;
    };
    CallTarget target{.kind = CallKind::StandardFunction, .name = name};
    const sema::Type* result = nullptr;
    if (name == "ABS" || name == "MOVE" || kReal1.contains(name)) {
        if (!count(1, 1)) {
            return nullptr;
        }
        const bool real = kReal1.contains(name);
        const sema::Type* operand =
            type(*values[0], real && (expected == nullptr || !sema::is_real(*expected))
                                 ? &elementary(E::Lreal)
                                 : expected);
        if (operand == nullptr) {
            return nullptr;
        }
        operand = &program_.types().unranged(*operand);
        if (real && !sema::is_real(*operand)) {
            return fail(DiagnosticCode::E0305, range,
                        fmt::format("{} needs a REAL or LREAL, not {}", name, operand->name));
        }
        if (name == "ABS" && !sema::is_numeric(*operand)) {
            return fail(DiagnosticCode::E0305, range,
                        fmt::format("ABS needs a number, not {}", operand->name));
        }
        target.operand = result = operand;
    } else if (name == "ATAN2" || name == "EXPT") {
        if (!count(2, 2)) {
            return nullptr;
        }
        const sema::Type* real =
            expected != nullptr && sema::is_real(*expected) ? expected : &elementary(E::Lreal);
        const sema::Type* base =
            name == "ATAN2" ? unify(values, real, range) : type(*values[0], real);
        if (name == "EXPT") {
            type(*values[1], nullptr);
        }
        if (base == nullptr) {
            return nullptr;
        }
        target.operand = result = sema::is_real(*base) ? base : &elementary(E::Lreal);
    } else if (kArithmetic.contains(name) || kBitwise.contains(name) || name == "NOT" ||
               name == "MAX" || name == "MIN") {
        // SUB, DIV and MOD take two inputs, NOT one; the others are extensible (table 24).
        const std::size_t low = name == "NOT" ? 1 : 2;
        const bool extensible = name != "NOT" && name != "SUB" && name != "DIV" && name != "MOD";
        if (!count(low, extensible ? 64 : low)) {
            return nullptr;
        }
        result = unify(values, expected, range);
        if (result != nullptr && (kArithmetic.contains(name)) && !sema::is_numeric(*result) &&
            !sema::is_bit_string(*result)) {
            return fail(DiagnosticCode::E0305, range,
                        fmt::format("{} needs numbers, not {}", name, result->name));
        }
        target.operand = result;
    } else if (kComparison.contains(name)) {
        if (!count(2, 64)) {
            return nullptr;
        }
        target.operand = unify(values, nullptr, range);
        result = target.operand != nullptr ? &elementary(E::Bool) : nullptr;
    } else if (kShift.contains(name)) {
        if (!count(2, 2)) {
            return nullptr;
        }
        target.operand = result = type(*values[0], expected);
        integer(*values[1]);
    } else if (name == "SEL") {
        if (!count(3, 3)) {
            return nullptr;
        }
        condition(*values[0]);
        target.operand = result = unify({values[1], values[2]}, expected, range);
    } else if (name == "MUX") {
        if (!count(2, 64)) {
            return nullptr;
        }
        integer(*values[0]);
        target.operand = result = unify(
            std::vector<const ast::Expression*>(values.begin() + 1, values.end()), expected, range);
    } else if (name == "LIMIT") {
        if (!count(3, 3)) {
            return nullptr;
        }
        target.operand = result = unify(values, expected, range);
    } else if (name == "LEN" || name == "FIND" || name == "LEFT" || name == "RIGHT" ||
               name == "MID" || name == "CONCAT" || name == "INSERT" || name == "DELETE" ||
               name == "REPLACE") {
        // Table 36: the texts first, then the lengths and positions (ANY_INT).
        const std::size_t texts = name == "CONCAT"                                          ? 64
                                  : name == "FIND" || name == "INSERT" || name == "REPLACE" ? 2
                                                                                            : 1;
        const std::size_t numbers = name == "LEFT" || name == "RIGHT" || name == "INSERT"    ? 1
                                    : name == "MID" || name == "DELETE" || name == "REPLACE" ? 2
                                                                                             : 0;
        if (!count(name == "CONCAT" ? 1 : texts + numbers,
                   name == "CONCAT" ? 64 : texts + numbers)) {
            return nullptr;
        }
        // The result holds whatever the inputs can make: the sum of their capacities for
        // CONCAT, INSERT and REPLACE, the largest for the others.
        std::uint32_t capacity = 0;
        bool wide = false;
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (i >= texts && name != "CONCAT") {
                integer(*values[i]);
                continue;
            }
            const sema::Type* text = string(*values[i]);
            if (text == nullptr) {
                return nullptr;
            }
            if (i > 0 && text->wide != wide) {
                return fail(DiagnosticCode::E0305, values[i]->range,
                            fmt::format("{} needs a {} here, not {}", name,
                                        wide ? "WSTRING" : "STRING", text->name));
            }
            wide = text->wide;
            capacity = texts > 2 || name == "INSERT" || name == "REPLACE"
                           ? capacity + text->capacity
                           : std::max(capacity, text->capacity);
        }
        if (name == "LEN" || name == "FIND") {
            result = &elementary(E::Int);
        } else {
            result = &program_.types().string(std::min<std::uint32_t>(capacity, 0xFFFF), wide);
        }
    } else if (name == "LOWER_BOUND" || name == "UPPER_BOUND") {
        if (!count(2, 2)) {
            return nullptr;
        }
        const sema::Type* array = type(*values[0], nullptr);
        type(*values[1], &elementary(E::Dint));
        if (array != nullptr && array->kind != sema::TypeKind::Array) {
            return fail(DiagnosticCode::E0305, values[0]->range,
                        fmt::format("{} needs an array, not {}", name, array->name));
        }
        const auto dimension = program_.types().fold_integer(*values[1]);
        if (array != nullptr &&
            (!dimension || *dimension < 1 ||
             *dimension > static_cast<std::int64_t>(array->dimensions.size()))) {
            return fail(DiagnosticCode::E0313, values[1]->range,
                        fmt::format("the dimension must be a constant from 1 to {}",
                                    array->dimensions.size()));
        }
        result = &elementary(E::Dint);
    } else if (const auto time = time_function(name)) {
        // Table 30: fixed signatures; MUL_TIME and DIV_TIME scale by any number.
        if (!count(2, 2)) {
            return nullptr;
        }
        expect(*values[0], elementary(time->first), "a time");
        if (time->second) {
            expect(*values[1], elementary(*time->second), "a time");
        } else {
            const sema::Type* factor = type(*values[1], &elementary(E::Lint));
            if (factor != nullptr && !sema::is_numeric(*factor)) {
                return fail(DiagnosticCode::E0305, range,
                            fmt::format("{} scales by a number, not {}", name, factor->name));
            }
        }
        target.operand = &elementary(time->first);
        result = &elementary(time_result(name));
    } else if (name == "ADR" || name == "SIZEOF") {
        if (!count(1, 1)) {
            return nullptr;
        }
        const sema::Type* object = type(*values[0], nullptr);
        if (object == nullptr) {
            return nullptr;
        }
        // ADR is an address for any POINTER TO; SIZEOF fits the smallest unsigned type
        // (docs/st-language.md, references and pointers).
        result = name == "ADR"            ? &program_.types().reference(nullptr)
                 : object->size <= 0xFF   ? &elementary(E::Usint)
                 : object->size <= 0xFFFF ? &elementary(E::Uint)
                                          : &elementary(E::Udint);
    } else {
        return fail(DiagnosticCode::E0504, range,
                    fmt::format("the typing stage does not know {} yet", name));
    }
    if (result == nullptr) {
        return nullptr;
    }
    target.result = result;
    program_.set_call(expression, target);
    return result;
}

} // namespace eposp::compiler::types
