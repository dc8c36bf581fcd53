// Initial values written as the image holds them (ed. 3, 6.5.1.3, 6.4.2), as the constant
// evaluator (constant_evaluator.cpp) computes them.

#include "initial_constant.hpp"

#include "eposp/vm/stdlib/string_layout.hpp"

#include <cstring>
#include <fmt/format.h>

namespace eposp::compiler::types {

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

std::optional<std::vector<std::uint8_t>> text_bytes(const ast::Literal* literal,
                                                    const sema::Type& type) {
    const auto* text = literal != nullptr ? std::get_if<ast::StringLiteral>(literal) : nullptr;
    if (text == nullptr) {
        return std::nullopt;
    }
    if (type.kind == sema::TypeKind::String) {
        if (const auto* narrow = std::get_if<std::string>(&text->value)) {
            return type.wide ? std::nullopt
                             : std::optional(vm::stdlib::string_image(type.capacity, *narrow));
        }
        return type.wide ? std::optional(vm::stdlib::wstring_image(
                               type.capacity, std::get<std::u16string>(text->value)))
                         : std::nullopt;
    }
    // CHAR#'A' / WCHAR#"A": the one character's code (the decoder checked the length).
    if (text->type != type.elementary) {
        return std::nullopt;
    }
    const std::int64_t code =
        type.elementary == ast::ElementaryType::Char
            ? static_cast<std::uint8_t>(std::get<std::string>(text->value).front())
            : std::int64_t{std::get<std::u16string>(text->value).front()};
    return integer_bytes(code, type.size);
}

/// The bytes of the typing stage's constant of `expression` (a standard function's,
/// `SHL(WORD#1, 4)`) as a value of the scalar `type`; E0311 for an integer it does not hold.
std::optional<std::variant<std::vector<std::uint8_t>, ConstantRefusal>>
typed_bytes(const ast::Expression& expression, const sema::Type& type,
            const ConstantEvaluator& constants);

} // namespace

std::vector<std::uint8_t> integer_bytes(std::int64_t value, std::uint32_t size) {
    std::vector<std::uint8_t> bytes(size);
    const auto raw = static_cast<std::uint64_t>(value);
    for (std::uint32_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(raw >> (8 * i));
    }
    return bytes;
}

namespace {

std::optional<std::variant<std::vector<std::uint8_t>, ConstantRefusal>>
typed_bytes(const ast::Expression& expression, const sema::Type& type,
            const ConstantEvaluator& constants) {
    const auto value = constants.typed_as(expression, type);
    if (!value || !sema::is_scalar(type) || type.kind == sema::TypeKind::Reference) {
        return std::nullopt;
    }
    if ((sema::is_integer(type) || sema::is_bit_string(type)) &&
        !constants.typed_fits(expression, type)) {
        return ConstantRefusal{DiagnosticCode::E0311,
                               fmt::format("the value does not fit in {}", type.name)};
    }
    return std::visit(
        [&](const auto& v)
            -> std::optional<std::variant<std::vector<std::uint8_t>, ConstantRefusal>> {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, bool>) {
                return integer_bytes(v ? 1 : 0, type.size);
            } else if constexpr (std::is_same_v<V, double>) {
                return type.size == 4 ? bytes_of(static_cast<float>(v)) : bytes_of(v);
            } else if constexpr (std::is_same_v<V, std::string>) {
                return std::nullopt;
            } else {
                return integer_bytes(static_cast<std::int64_t>(v), type.size);
            }
        },
        *value);
}

/// constant_bytes() as the evaluator folds the expression itself.
std::variant<std::vector<std::uint8_t>, ConstantRefusal>
folded_bytes(const ast::Expression& expression, const sema::Type& type,
             const ConstantEvaluator& constants) {
    const ConstantRefusal not_constant{
        DiagnosticCode::E0313, fmt::format("the initial value must be a constant {}", type.name)};
    const auto or_refused = [&](std::optional<std::vector<std::uint8_t>> bytes)
        -> std::variant<std::vector<std::uint8_t>, ConstantRefusal> {
        if (bytes) {
            return std::move(*bytes);
        }
        return not_constant;
    };
    if (type.kind == sema::TypeKind::String || type.elementary == ast::ElementaryType::Char ||
        type.elementary == ast::ElementaryType::Wchar) {
        return or_refused(sema::is_scalar(type) || type.kind == sema::TypeKind::String
                              ? text_bytes(constants.literal(expression), type)
                              : std::nullopt);
    }
    if (!sema::is_scalar(type)) {
        return not_constant;
    }
    if (sema::is_real(type)) {
        const auto value = constants.real(expression, type.size == 4);
        if (!value) {
            return not_constant;
        }
        return type.size == 4 ? bytes_of(static_cast<float>(*value)) : bytes_of(*value);
    }
    if (sema::is_time_like(type)) {
        const auto value =
            constants.time(expression, type.elementary == ast::ElementaryType::TimeOfDay ||
                                           type.elementary == ast::ElementaryType::Ltod);
        return or_refused(value ? std::optional(bytes_of(*value)) : std::nullopt);
    }
    if (sema::is_bool(type)) {
        if (const auto value = constants.boolean(expression)) {
            return integer_bytes(*value ? 1 : 0, type.size);
        }
    }
    const ast::Literal* literal = constants.literal(expression);
    if (literal != nullptr) {
        if (const auto* boolean = std::get_if<ast::BoolLiteral>(literal)) {
            return or_refused(sema::is_bool(type) || sema::is_bit_string(type) ||
                                      sema::is_integer(type)
                                  ? std::optional(integer_bytes(boolean->value ? 1 : 0, type.size))
                                  : std::nullopt);
        }
        if (std::holds_alternative<ast::NullLiteral>(*literal)) {
            return or_refused(type.kind == sema::TypeKind::Reference
                                  ? std::optional(std::vector<std::uint8_t>(8, 0))
                                  : std::nullopt);
        }
    }
    if (type.kind == sema::TypeKind::Reference) {
        return not_constant;
    }
    const auto* written = std::get_if<ast::LiteralExpression>(&expression.node);
    if (const auto* integer =
            written != nullptr ? std::get_if<ast::IntegerLiteral>(&written->value) : nullptr) {
        // Directly from the magnitude, so that ULINT values above LINT's range work.
        const auto range = ast::integer_range(type.elementary);
        const bool fits =
            integer->negative
                ? range && integer->magnitude <= static_cast<std::uint64_t>(-(range->min + 1)) + 1
                : !range || integer->magnitude <= range->max;
        if (!fits && type.kind != sema::TypeKind::Enum) {
            return ConstantRefusal{DiagnosticCode::E0311,
                                   fmt::format("the value {}{} does not fit in {}",
                                               integer->negative ? "-" : "", integer->magnitude,
                                               type.name)};
        }
        const std::uint64_t bits = integer->negative ? 0 - integer->magnitude : integer->magnitude;
        return integer_bytes(static_cast<std::int64_t>(bits), type.size);
    }
    const auto bits = constants.fold_as(expression, type);
    if (!bits) {
        return not_constant;
    }
    // ULINT and LWORD take any 64 bits; the others must hold the value their arithmetic gave.
    const auto value = static_cast<std::int64_t>(*bits);
    if (sema::scalar_of(type) != vm::Scalar::U64 && !fits_integer(value, type) &&
        type.kind != sema::TypeKind::Enum) {
        return ConstantRefusal{DiagnosticCode::E0311,
                               fmt::format("the value {} does not fit in {}", value, type.name)};
    }
    // Nor a value that the 32 bits of DINT's, UDINT's or DWORD's own arithmetic wrapped: out
    // of the type's range as much as 100 + 100 in a SINT. The value in 64 bits tells (a
    // LINT's or ULINT's own overflow is not seen: their constants are 64-bit patterns there).
    const bool computed = std::holds_alternative<ast::BinaryExpression>(expression.node) ||
                          std::holds_alternative<ast::UnaryExpression>(expression.node);
    const auto exact = computed && type.kind != sema::TypeKind::Enum &&
                               sema::scalar_of(type) != vm::Scalar::I64 &&
                               sema::scalar_of(type) != vm::Scalar::U64
                           ? constants.fold_integer(expression)
                           : std::nullopt;
    // value_or: GCC's -O2 cannot see that `exact` is set where it is read.
    const std::int64_t wide = exact.value_or(0);
    const bool wrapped = exact.has_value() && wide != value;
    if (wrapped) {
        return ConstantRefusal{DiagnosticCode::E0311,
                               fmt::format("the value {} does not fit in {}", wide, type.name)};
    }
    return integer_bytes(value, type.size);
}

} // namespace

std::variant<std::vector<std::uint8_t>, ConstantRefusal>
constant_bytes(const ast::Expression& expression, const sema::Type& type,
               const ConstantEvaluator& constants) {
    auto bytes = folded_bytes(expression, type, constants);
    const auto* refusal = std::get_if<ConstantRefusal>(&bytes);
    if (refusal != nullptr && refusal->code == DiagnosticCode::E0313) {
        if (auto typed = typed_bytes(expression, type, constants)) {
            return std::move(*typed);
        }
    }
    return bytes;
}

} // namespace eposp::compiler::types
