// Constant expressions of initial values folded to the image's bytes (ed. 3, 6.5.1.3, 6.4.2).

#include "initial_constant.hpp"

#include "eposp/compiler/sema/symbol.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"

#include <cstring>
#include <fmt/format.h>
#include <optional>
#include <unordered_set>

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

const ast::Literal* literal_of(const ast::Expression& expression) {
    const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node);
    return literal != nullptr ? &literal->value : nullptr;
}

/// Folds REAL and TIME expressions and finds the values of named constants; integers are the
/// type table's (TypeTable::fold_integer).
class Folder {
public:
    explicit Folder(sema::TypeTable& types) : types_(types) {}

    /// The initial value of the CONSTANT `expression` names, with its declared type; null when
    /// it names none (or one defined through itself).
    std::pair<const ast::Expression*, const sema::Type*>
    constant(const ast::Expression& expression) {
        const auto* name = std::get_if<ast::NameExpression>(&expression.node);
        const sema::Symbol* symbol =
            name != nullptr ? types_.model().resolved(name->name) : nullptr;
        if (symbol == nullptr || symbol->kind != sema::SymbolKind::Variable ||
            symbol->variable == nullptr || !symbol->variable->initial_value ||
            !types_.is_constant(*symbol->variable) || folding_.contains(symbol->variable)) {
            return {nullptr, nullptr};
        }
        const auto* value =
            std::get_if<ast::ExpressionPtr>(&symbol->variable->initial_value->value);
        if (value == nullptr) {
            return {nullptr, nullptr};
        }
        return {value->get(), types_.resolve(symbol->variable->type)};
    }

    /// A constant REAL or LREAL expression (`1.0 / 3.0`, `Ratio * 2.0`); `single`: a REAL,
    /// whose every value and operation rounds to single precision as it does at run time
    /// (`16777216.0 + 1.0 + 1.0` is 16777216.0, not 16777218.0 rounded once at the end).
    std::optional<double> real(const ast::Expression& expression, bool single) {
        const auto rounded = [single](double value) {
            return single ? static_cast<double>(static_cast<float>(value)) : value;
        };
        if (const ast::Literal* literal = literal_of(expression)) {
            if (const auto* real = std::get_if<ast::RealLiteral>(literal)) {
                return rounded(real->value);
            }
            if (const auto* integer = std::get_if<ast::IntegerLiteral>(literal)) {
                return rounded(static_cast<double>(integer->magnitude) *
                               (integer->negative ? -1 : 1));
            }
            return std::nullopt;
        }
        if (const auto [initial, type] = constant(expression); initial != nullptr) {
            // A named constant has the value of its own type (a REAL one in an LREAL too).
            if (type != nullptr && sema::is_real(*type)) {
                const bool its_single = type->size == 4;
                return within(expression, [&] { return real(*initial, its_single); });
            }
            const auto integer = types_.fold_integer(expression);
            return integer ? std::optional(rounded(static_cast<double>(*integer))) : std::nullopt;
        }
        if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
            const auto operand = real(*unary->operand, single);
            if (!operand || unary->op == ast::UnaryOperator::Not) {
                return std::nullopt;
            }
            return unary->op == ast::UnaryOperator::Negate ? -*operand : *operand;
        }
        const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
        const auto left = binary != nullptr ? real(*binary->left, single) : std::nullopt;
        const auto right = left ? real(*binary->right, single) : std::nullopt;
        if (!right) {
            return std::nullopt;
        }
        switch (binary->op) {
        case ast::BinaryOperator::Add:
            return rounded(*left + *right);
        case ast::BinaryOperator::Subtract:
            return rounded(*left - *right);
        case ast::BinaryOperator::Multiply:
            return rounded(*left * *right);
        case ast::BinaryOperator::Divide:
            return rounded(*left / *right);
        default:
            return std::nullopt;
        }
    }

    /// A constant duration or point in time in ns (table 30: `T#1ms * 4`, `DT#... + T#1h`);
    /// `day_wraps`: a TIME_OF_DAY, whose sums wrap around midnight.
    std::optional<std::int64_t> time(const ast::Expression& expression, bool day_wraps) {
        if (const ast::Literal* literal = literal_of(expression)) {
            if (const auto* duration = std::get_if<ast::DurationLiteral>(literal)) {
                return duration->nanoseconds;
            }
            if (const auto* date = std::get_if<ast::DateTimeLiteral>(literal)) {
                return date->nanoseconds;
            }
            return std::nullopt;
        }
        if (const auto [initial, type] = constant(expression); initial != nullptr) {
            return type != nullptr && sema::is_time_like(*type)
                       ? within(expression, [&] { return time(*initial, day_wraps); })
                       : std::nullopt;
        }
        if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
            const auto operand = time(*unary->operand, day_wraps);
            if (!operand || unary->op == ast::UnaryOperator::Not) {
                return std::nullopt;
            }
            return unary->op == ast::UnaryOperator::Negate ? wrap(0, *operand, false) : *operand;
        }
        const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
        if (binary == nullptr) {
            return std::nullopt;
        }
        const auto left = time(*binary->left, false);
        switch (binary->op) {
        case ast::BinaryOperator::Add:
        case ast::BinaryOperator::Subtract: {
            // A TIME_OF_DAY wraps around midnight at run time (ADD_TOD_TIME): not folded.
            const auto right = left && !day_wraps ? time(*binary->right, false) : std::nullopt;
            return right
                       ? std::optional(wrap(*left, *right, binary->op == ast::BinaryOperator::Add))
                       : std::nullopt;
        }
        case ast::BinaryOperator::Multiply: {
            // TIME * ANY_INT as MUL_TIME computes it: modulo 2^64. A REAL factor rounds at run
            // time (MUL_TIME_LREAL): not folded.
            const auto factor = left ? types_.fold_integer(*binary->right) : std::nullopt;
            return factor ? std::optional(
                                static_cast<std::int64_t>(static_cast<std::uint64_t>(*left) *
                                                          static_cast<std::uint64_t>(*factor)))
                          : std::nullopt;
        }
        case ast::BinaryOperator::Divide: {
            // As DIV_TIME: / -1 wraps, / 0 is no constant.
            const auto divisor = left ? types_.fold_integer(*binary->right) : std::nullopt;
            if (!divisor || *divisor == 0) {
                return std::nullopt;
            }
            return *divisor == -1 ? wrap(0, *left, false) : *left / *divisor;
        }
        default:
            return std::nullopt;
        }
    }

    /// A BOOL constant: TRUE, FALSE, a BOOL CONSTANT, and NOT, AND, OR, XOR of those.
    std::optional<bool> boolean(const ast::Expression& expression) {
        if (const ast::Literal* literal = literal_of(expression)) {
            const auto* boolean = std::get_if<ast::BoolLiteral>(literal);
            return boolean != nullptr ? std::optional(boolean->value) : std::nullopt;
        }
        if (const auto [initial, type] = constant(expression); initial != nullptr) {
            return type != nullptr && sema::is_bool(*type)
                       ? within(expression, [&] { return boolean(*initial); })
                       : std::nullopt;
        }
        if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
            const auto operand = boolean(*unary->operand);
            return operand && unary->op == ast::UnaryOperator::Not ? std::optional(!*operand)
                                                                   : std::nullopt;
        }
        const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node);
        const auto left = binary != nullptr ? boolean(*binary->left) : std::nullopt;
        const auto right = left ? boolean(*binary->right) : std::nullopt;
        if (!right) {
            return std::nullopt;
        }
        switch (binary->op) {
        case ast::BinaryOperator::And:
            return *left && *right;
        case ast::BinaryOperator::Or:
            return *left || *right;
        case ast::BinaryOperator::Xor:
            return *left != *right;
        default:
            return std::nullopt;
        }
    }

    /// A BOOL, CHAR or STRING constant: the literal it is or a CONSTANT names.
    const ast::Literal* literal(const ast::Expression& expression) {
        if (const ast::Literal* literal = literal_of(expression)) {
            return literal;
        }
        const auto [initial, type] = constant(expression);
        return initial != nullptr ? within(expression, [&] { return literal(*initial); }) : nullptr;
    }

private:
    static std::int64_t wrap(std::int64_t a, std::int64_t b, bool add) {
        const auto ua = static_cast<std::uint64_t>(a);
        const auto ub = static_cast<std::uint64_t>(b);
        return static_cast<std::int64_t>(add ? ua + ub : ua - ub);
    }

    /// `fold()` with the constant `name` names marked as being folded.
    template <typename Fold>
    auto within(const ast::Expression& name, Fold fold) -> decltype(fold()) {
        const ast::VariableDeclaration* declaration =
            types_.model().resolved(std::get<ast::NameExpression>(name.node).name)->variable;
        folding_.insert(declaration);
        auto value = fold();
        folding_.erase(declaration);
        return value;
    }

    sema::TypeTable& types_;
    std::unordered_set<const ast::VariableDeclaration*> folding_;
};

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

} // namespace

std::vector<std::uint8_t> integer_bytes(std::int64_t value, std::uint32_t size) {
    std::vector<std::uint8_t> bytes(size);
    const auto raw = static_cast<std::uint64_t>(value);
    for (std::uint32_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(raw >> (8 * i));
    }
    return bytes;
}

std::variant<std::vector<std::uint8_t>, ConstantRefusal>
constant_bytes(const ast::Expression& expression, const sema::Type& type, sema::TypeTable& types) {
    Folder folder(types);
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
                              ? text_bytes(folder.literal(expression), type)
                              : std::nullopt);
    }
    if (!sema::is_scalar(type)) {
        return not_constant;
    }
    if (sema::is_real(type)) {
        const auto value = folder.real(expression, type.size == 4);
        if (!value) {
            return not_constant;
        }
        return type.size == 4 ? bytes_of(static_cast<float>(*value)) : bytes_of(*value);
    }
    if (sema::is_time_like(type)) {
        const auto value =
            folder.time(expression, type.elementary == ast::ElementaryType::TimeOfDay ||
                                        type.elementary == ast::ElementaryType::Ltod);
        return or_refused(value ? std::optional(bytes_of(*value)) : std::nullopt);
    }
    if (sema::is_bool(type)) {
        if (const auto value = folder.boolean(expression)) {
            return integer_bytes(*value ? 1 : 0, type.size);
        }
    }
    const ast::Literal* literal = folder.literal(expression);
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
    if (const auto* integer = literal_of(expression) != nullptr
                                  ? std::get_if<ast::IntegerLiteral>(literal_of(expression))
                                  : nullptr) {
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
    const auto bits = types.fold_as(expression, type);
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
    return integer_bytes(value, type.size);
}

} // namespace eposp::compiler::types
