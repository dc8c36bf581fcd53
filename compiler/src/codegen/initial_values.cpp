// Initial values of variables (IEC 61131-3 ed. 3, 6.5.1.3 and 6.4.2): the type's default
// (zero, an empty STRING with its capacity in the header), the declared defaults of structure
// members and FB variables, then the initializer written at the declaration.

#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"
#include "program_generator.hpp"

#include <algorithm>
#include <cstring>
#include <fmt/format.h>

namespace eposp::compiler::codegen {

namespace {

template <typename T>
std::vector<std::uint8_t> bytes_of(T value) {
    std::vector<std::uint8_t> bytes(sizeof(T));
    std::memcpy(bytes.data(), &value, sizeof(T));
    return bytes;
}

bool fits_integer(std::int64_t value, const sema::Type& type) {
    const auto range = ast::integer_range(type.elementary);
    return !range ||
           (value >= range->min && (value < 0 || static_cast<std::uint64_t>(value) <= range->max));
}

/// A constant REAL expression: literals, signs and + - * / of them (ed. 3, 6.4.2 initial
/// values such as `1.0 / 3.0`).
std::optional<double> fold_real(const ast::Expression& expression) {
    if (const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node)) {
        if (const auto* real = std::get_if<ast::RealLiteral>(&literal->value)) {
            return real->value;
        }
        if (const auto* integer = std::get_if<ast::IntegerLiteral>(&literal->value)) {
            return static_cast<double>(integer->magnitude) * (integer->negative ? -1 : 1);
        }
        return std::nullopt;
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        const auto operand = fold_real(*unary->operand);
        if (!operand || unary->op == ast::UnaryOperator::Not) {
            return std::nullopt;
        }
        return unary->op == ast::UnaryOperator::Negate ? -*operand : *operand;
    }
    const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
    const auto left = binary != nullptr ? fold_real(*binary->left) : std::nullopt;
    const auto right = left ? fold_real(*binary->right) : std::nullopt;
    if (!right) {
        return std::nullopt;
    }
    switch (binary->op) {
    case ast::BinaryOperator::Add:
        return *left + *right;
    case ast::BinaryOperator::Subtract:
        return *left - *right;
    case ast::BinaryOperator::Multiply:
        return *left * *right;
    case ast::BinaryOperator::Divide:
        return *left / *right;
    default:
        return std::nullopt;
    }
}

} // namespace

std::vector<std::uint8_t> integer_bytes(std::int64_t value, std::uint32_t size) {
    std::vector<std::uint8_t> bytes(size);
    const auto raw = static_cast<std::uint64_t>(value);
    for (std::uint32_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(raw >> (8 * i));
    }
    return bytes;
}

std::optional<std::vector<std::uint8_t>>
ProgramGenerator::constant_value(const ast::Expression& expression, const sema::Type& type) {
    const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node);
    if (type.kind == sema::TypeKind::String) {
        const auto* text =
            literal != nullptr ? std::get_if<ast::StringLiteral>(&literal->value) : nullptr;
        if (text == nullptr) {
            return std::nullopt;
        }
        if (const auto* narrow = std::get_if<std::string>(&text->value)) {
            return type.wide ? std::nullopt
                             : std::optional(vm::stdlib::string_image(type.capacity, *narrow));
        }
        return type.wide ? std::optional(vm::stdlib::wstring_image(
                               type.capacity, std::get<std::u16string>(text->value)))
                         : std::nullopt;
    }
    if (!sema::is_scalar(type)) {
        return std::nullopt;
    }
    if (type.elementary == ast::ElementaryType::Char ||
        type.elementary == ast::ElementaryType::Wchar) {
        // CHAR#'A' / WCHAR#"A": the one character's code (the decoder checked the length).
        const auto* text =
            literal != nullptr ? std::get_if<ast::StringLiteral>(&literal->value) : nullptr;
        if (text == nullptr || text->type != type.elementary) {
            return std::nullopt;
        }
        const std::int64_t code =
            type.elementary == ast::ElementaryType::Char
                ? static_cast<std::uint8_t>(std::get<std::string>(text->value).front())
                : std::int64_t{std::get<std::u16string>(text->value).front()};
        return integer_bytes(code, type.size);
    }
    if (sema::is_real(type)) {
        const auto value = fold_real(expression);
        if (!value) {
            return std::nullopt;
        }
        return type.size == 4 ? bytes_of(static_cast<float>(*value)) : bytes_of(*value);
    }
    if (literal != nullptr) {
        if (const auto* boolean = std::get_if<ast::BoolLiteral>(&literal->value)) {
            return sema::is_bool(type) || sema::is_bit_string(type) || sema::is_integer(type)
                       ? std::optional(integer_bytes(boolean->value ? 1 : 0, type.size))
                       : std::nullopt;
        }
        if (const auto* duration = std::get_if<ast::DurationLiteral>(&literal->value)) {
            return sema::is_time_like(type) ? std::optional(bytes_of(duration->nanoseconds))
                                            : std::nullopt;
        }
        if (const auto* date = std::get_if<ast::DateTimeLiteral>(&literal->value)) {
            return sema::is_time_like(type) ? std::optional(bytes_of(date->nanoseconds))
                                            : std::nullopt;
        }
        if (std::holds_alternative<ast::NullLiteral>(literal->value)) {
            return type.kind == sema::TypeKind::Reference
                       ? std::optional(std::vector<std::uint8_t>(8, 0))
                       : std::nullopt;
        }
    }
    if (type.kind == sema::TypeKind::Reference || sema::is_real(type) || sema::is_time_like(type)) {
        return std::nullopt;
    }
    if (literal != nullptr) {
        if (const auto* integer = std::get_if<ast::IntegerLiteral>(&literal->value)) {
            // Directly from the magnitude, so that ULINT values above LINT's range work.
            const auto range = ast::integer_range(type.elementary);
            const bool fits = integer->negative
                                  ? range && integer->magnitude <=
                                                 static_cast<std::uint64_t>(-(range->min + 1)) + 1
                                  : !range || integer->magnitude <= range->max;
            if (!fits && type.kind != sema::TypeKind::Enum) {
                diagnostics_.error(DiagnosticCode::E0311, expression.range,
                                   fmt::format("the value {}{} does not fit in {}",
                                               integer->negative ? "-" : "", integer->magnitude,
                                               type.name));
            }
            const std::uint64_t bits =
                integer->negative ? 0 - integer->magnitude : integer->magnitude;
            return integer_bytes(static_cast<std::int64_t>(bits), type.size);
        }
    }
    const auto value = types_.fold_integer(expression);
    if (!value) {
        return std::nullopt;
    }
    if (!fits_integer(*value, type) && type.kind != sema::TypeKind::Enum) {
        diagnostics_.error(DiagnosticCode::E0311, expression.range,
                           fmt::format("the value {} does not fit in {}", *value, type.name));
    }
    return integer_bytes(*value, type.size);
}

void ProgramGenerator::initial_value(const sema::Type& type, const ast::Initializer* initializer,
                                     std::span<std::uint8_t> bytes) {
    const std::vector<std::uint8_t>& defaults = default_value(type);
    std::copy(defaults.begin(), defaults.end(), bytes.begin());
    if (initializer != nullptr) {
        apply_initializer(type, *initializer, bytes);
    }
}

// Computed once per type, so that an error in a member's initializer is reported once, not
// once per array element or variable of the type.
const std::vector<std::uint8_t>& ProgramGenerator::default_value(const sema::Type& type) {
    if (const auto it = default_values_.find(&type); it != default_values_.end()) {
        return it->second;
    }
    std::vector<std::uint8_t> bytes(type.size);
    switch (type.kind) {
    case sema::TypeKind::String: {
        const auto empty = vm::stdlib::string_image(type.capacity, "");
        std::copy(empty.begin(), empty.begin() + vm::stdlib::kStringHeaderSize, bytes.begin());
        break;
    }
    case sema::TypeKind::Array: {
        const std::vector<std::uint8_t>& element = default_value(*type.element);
        for (auto at = bytes.begin(); !element.empty() && at != bytes.end(); at += element.size()) {
            std::copy(element.begin(), element.end(), at);
        }
        break;
    }
    case sema::TypeKind::Struct:
    case sema::TypeKind::Instance:
        for (const sema::Type* part = &type; part != nullptr; part = part->base) {
            for (const sema::Field& field : part->fields) {
                if (field.section == ast::VarSectionKind::InOut) {
                    continue; // a reference, bound at each call
                }
                initial_value(*field.type,
                              field.declaration != nullptr ? field.declaration->initial_value.get()
                                                           : nullptr,
                              std::span(bytes).subspan(field.offset, field.type->size));
            }
        }
        break;
    case sema::TypeKind::Enum:
        // 6.4.4.2: an enumerated type starts at its first value, whatever number that has.
        if (!type.enumerators.empty()) {
            const auto first = integer_bytes(type.enumerators.front().second, type.size);
            std::copy(first.begin(), first.end(), bytes.begin());
        }
        break;
    default:
        if (type.range) {
            // 6.4.4.4: a subrange starts at its lower bound, not at 0.
            const auto lower = integer_bytes(type.range->lower, type.size);
            std::copy(lower.begin(), lower.end(), bytes.begin());
        }
        break;
    }
    // 6.4.2: the default a type declaration gives (`TYPE Speed : INT := 100;`).
    if (type.initial_value != nullptr) {
        apply_initializer(type, *type.initial_value, bytes);
    }
    return default_values_[&type] = std::move(bytes);
}

// 6.4.4.2: a variable of an enumerated type holds one of the type's values: one of its names,
// or a constant (or number, as CODESYS allows) equal to one of them.
bool ProgramGenerator::is_enumerator_of(const ast::Expression& expression,
                                        const sema::Type& enumeration) {
    if (const sema::Symbol* value = program_.model.enum_value(expression)) {
        const sema::Type* owner = types_.enumeration_of(*value);
        return owner != nullptr && sema::same_type(*owner, enumeration);
    }
    const auto number = types_.fold_integer(expression);
    return number && std::ranges::any_of(enumeration.enumerators, [&](const auto& enumerator) {
               return enumerator.second == *number;
           });
}

void ProgramGenerator::apply_initializer(const sema::Type& type,
                                         const ast::Initializer& initializer,
                                         std::span<std::uint8_t> bytes) {
    if (const auto* expression = std::get_if<ast::ExpressionPtr>(&initializer.value)) {
        if (type.kind == sema::TypeKind::Enum && !is_enumerator_of(**expression, type)) {
            diagnostics_.error(DiagnosticCode::E0301, (*expression)->range,
                               fmt::format("the initial value must be a value of {}", type.name));
            return;
        }
        if (const auto value = constant_value(**expression, type)) {
            std::copy(value->begin(), value->end(), bytes.begin());
        } else {
            diagnostics_.error(DiagnosticCode::E0313, (*expression)->range,
                               fmt::format("the initial value must be a constant {}", type.name));
        }
        return;
    }
    if (const auto* elements =
            std::get_if<std::vector<ast::ArrayInitElement>>(&initializer.value)) {
        if (type.kind != sema::TypeKind::Array) {
            diagnostics_.error(DiagnosticCode::E0301, initializer.range,
                               fmt::format("{} is not an array", type.name));
            return;
        }
        const std::uint32_t size = type.element->size;
        const std::uint32_t count = type.size / std::max<std::uint32_t>(size, 1);
        std::uint32_t next = 0;
        for (const ast::ArrayInitElement& element : *elements) {
            std::int64_t repeat = 1;
            if (element.repeat_count) {
                repeat = types_.fold_integer(*element.repeat_count).value_or(-1);
                if (repeat < 0) {
                    diagnostics_.error(DiagnosticCode::E0313, element.repeat_count->range,
                                       "a repetition count must be a constant >= 0");
                    return;
                }
            }
            for (std::int64_t i = 0; i < repeat; ++i, ++next) {
                if (next >= count) {
                    refused_by_checks(DiagnosticCode::E0411); // checks/initial_value_counts.cpp
                    return;
                }
                if (element.value) {
                    initial_value(*type.element, element.value.get(),
                                  bytes.subspan(next * size, size));
                }
            }
        }
        return;
    }
    const auto& members = std::get<std::vector<ast::StructInitElement>>(initializer.value);
    for (const ast::StructInitElement& member : members) {
        const sema::Field* field = type.field(member.member.name);
        if (field == nullptr ||
            (type.kind != sema::TypeKind::Struct && type.kind != sema::TypeKind::Instance)) {
            diagnostics_.error(
                DiagnosticCode::E0206, member.member.range,
                fmt::format("'{}' has no member '{}'", type.name, member.member.name));
            continue;
        }
        initial_value(*field->type, member.value.get(),
                      bytes.subspan(field->offset, field->type->size));
    }
}

} // namespace eposp::compiler::codegen
