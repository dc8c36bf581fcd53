// The constant the typing stage records for an expression (TypedProgram::constant_of).

#include "constant_evaluator.hpp"
#include "eposp/compiler/sema/symbol.hpp"

namespace eposp::compiler::types {

namespace {

std::optional<Constant> literal_value(const ast::Literal& literal, const sema::Type& type) {
    // A REAL literal has the single-precision value it has at run time.
    const auto rounded = [&type](double value) {
        return type.size == 4 ? static_cast<double>(static_cast<float>(value)) : value;
    };
    return std::visit(
        [&](const auto& value) -> std::optional<Constant> {
            using T = std::decay_t<decltype(value)>;
            if constexpr (std::is_same_v<T, ast::IntegerLiteral>) {
                if (sema::is_real(type)) {
                    const double magnitude = static_cast<double>(value.magnitude);
                    return rounded(value.negative ? -magnitude : magnitude);
                }
                if (sema::is_signed(type) || sema::is_time_like(type)) {
                    return value.negative ? static_cast<std::int64_t>(0 - value.magnitude)
                                          : static_cast<std::int64_t>(value.magnitude);
                }
                return value.magnitude;
            } else if constexpr (std::is_same_v<T, ast::RealLiteral>) {
                return sema::is_real(type) ? rounded(value.value) : value.value;
            } else if constexpr (std::is_same_v<T, ast::BoolLiteral>) {
                return value.value;
            } else if constexpr (std::is_same_v<T, ast::DurationLiteral> ||
                                 std::is_same_v<T, ast::DateTimeLiteral>) {
                return value.nanoseconds;
            } else if constexpr (std::is_same_v<T, ast::StringLiteral>) {
                const auto* text = std::get_if<std::string>(&value.value);
                if (text != nullptr && value.type == ast::ElementaryType::Char) {
                    // A CHAR is its character's code.
                    return static_cast<std::uint64_t>(
                        text->empty() ? 0 : static_cast<unsigned char>(text->front()));
                }
                return text != nullptr ? std::optional<Constant>(*text) : std::nullopt;
            } else {
                return std::nullopt;
            }
        },
        literal);
}

template <typename T>
std::optional<Constant> as_constant(const std::optional<T>& value) {
    return value ? std::optional<Constant>(*value) : std::nullopt;
}

} // namespace

std::optional<Constant> ConstantEvaluator::own_value(const ast::Expression& initial,
                                                     const sema::Type& own) const {
    if (auto folded = folded_value(initial, own)) {
        return folded;
    }
    // What the folding above does not cover (a standard function, `SHL(WORD#1, 4)`): the
    // constant the typing stage gave the initial value, stored into the constant's type.
    return typed_as(initial, own);
}

std::optional<Constant> ConstantEvaluator::typed_as(const ast::Expression& expression,
                                                    const sema::Type& type) const {
    const Constant* constant = program_.constant_of(expression);
    const sema::Type* from = program_.type_of(expression);
    return constant != nullptr && from != nullptr ? convert(*constant, types_.unranged(*from), type)
                                                  : std::nullopt;
}

bool ConstantEvaluator::typed_fits(const ast::Expression& expression,
                                   const sema::Type& type) const {
    const Constant* constant = program_.constant_of(expression);
    const sema::Type* from = program_.type_of(expression);
    const auto into = constant != nullptr && from != nullptr
                          ? convert(*constant, types_.unranged(*from), type)
                          : std::nullopt;
    // The same number, whether held signed or unsigned.
    const auto number = [](const Constant& c) -> std::optional<std::pair<bool, std::uint64_t>> {
        if (const auto* i = std::get_if<std::int64_t>(&c)) {
            return std::pair{*i < 0, static_cast<std::uint64_t>(*i)};
        }
        if (const auto* u = std::get_if<std::uint64_t>(&c)) {
            return std::pair{false, *u};
        }
        return std::nullopt;
    };
    return into && number(*into) && number(*into) == number(*constant);
}

std::optional<Constant> ConstantEvaluator::folded_value(const ast::Expression& initial,
                                                        const sema::Type& own) const {
    if (sema::is_real(own)) {
        return as_constant(real(initial, own.size == 4));
    }
    if (sema::is_time_like(own)) {
        return as_constant(time(initial, own.elementary == ast::ElementaryType::TimeOfDay ||
                                             own.elementary == ast::ElementaryType::Ltod));
    }
    if (sema::is_bool(own)) {
        return as_constant(boolean(initial));
    }
    if (own.kind != sema::TypeKind::Enum && (sema::is_integer(own) || sema::is_bit_string(own))) {
        const auto bits = fold_as(initial, own);
        if (!bits) {
            return std::nullopt;
        }
        return sema::is_signed(own) ? Constant{static_cast<std::int64_t>(*bits)} : Constant{*bits};
    }
    return value(initial, own); // an enumeration value, a CHAR, a STRING
}

std::optional<Constant> ConstantEvaluator::value(const ast::Expression& expression,
                                                 const sema::Type& type) const {
    if (const sema::Symbol* value = types_.model().enum_value(expression)) {
        return as_constant(types_.enumerator(*value));
    }
    if (const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node)) {
        return literal_value(literal->value, type);
    }
    if (const ast::VariableDeclaration* declaration = constant(expression)) {
        // A CONSTANT has the value its own type computes for its initial value.
        const sema::Type* own = types_.resolve(declaration->type);
        return own == nullptr ? std::nullopt : within(*declaration, [&] {
            return own_value(initial_value(*declaration), *own);
        });
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        return unary_value(*unary);
    }
    if (const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node)) {
        // Most operations are on variables: no constant, and nothing more to look at.
        if (program_.constant_of(*binary->left) == nullptr ||
            program_.constant_of(*binary->right) == nullptr) {
            return std::nullopt;
        }
        return binary_value(expression, *binary, type);
    }
    if (const auto* call = std::get_if<ast::CallExpression>(&expression.node)) {
        return call_value(expression, *call);
    }
    return std::nullopt;
}

} // namespace eposp::compiler::types
