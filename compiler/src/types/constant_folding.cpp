// The constant value of an expression, where the typing stage can tell it: literals,
// enumeration values, CONSTANT variables with a constant initial value, and a sign or NOT on
// one of those. Arithmetic on constants is left to the engines that run it.

#include "eposp/compiler/sema/symbol.hpp"
#include "expression_typer.hpp"

#include <cmath>

namespace eposp::compiler::types {

namespace {

bool is_constant(const sema::Symbol& symbol) {
    return symbol.kind == sema::SymbolKind::Variable && symbol.variable != nullptr &&
           symbol.variable->initial_value != nullptr &&
           std::holds_alternative<ast::ExpressionPtr>(symbol.variable->initial_value->value);
}

} // namespace

void ExpressionTyper::fold(const ast::Expression& expression, const sema::Type& type) {
    const bool is_signed = sema::is_signed(type) || sema::is_time_like(type);
    if (const sema::Symbol* value = model_.enum_value(expression)) {
        if (const auto number = program_.types().enumerator(*value)) {
            program_.set_constant(expression, *number);
        }
        return;
    }
    if (const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node)) {
        std::visit(
            [&](const auto& value) {
                using T = std::decay_t<decltype(value)>;
                if constexpr (std::is_same_v<T, ast::IntegerLiteral>) {
                    if (sema::is_real(type)) {
                        const double magnitude = static_cast<double>(value.magnitude);
                        program_.set_constant(expression, value.negative ? -magnitude : magnitude);
                    } else if (is_signed) {
                        program_.set_constant(expression,
                                              value.negative
                                                  ? static_cast<std::int64_t>(0 - value.magnitude)
                                                  : static_cast<std::int64_t>(value.magnitude));
                    } else {
                        program_.set_constant(expression, value.magnitude);
                    }
                } else if constexpr (std::is_same_v<T, ast::RealLiteral>) {
                    program_.set_constant(expression, value.value);
                } else if constexpr (std::is_same_v<T, ast::BoolLiteral>) {
                    program_.set_constant(expression, value.value);
                } else if constexpr (std::is_same_v<T, ast::DurationLiteral> ||
                                     std::is_same_v<T, ast::DateTimeLiteral>) {
                    program_.set_constant(expression, value.nanoseconds);
                } else if constexpr (std::is_same_v<T, ast::StringLiteral>) {
                    const auto* text = std::get_if<std::string>(&value.value);
                    if (text != nullptr && value.type == ast::ElementaryType::Char) {
                        // A CHAR is its character's code.
                        program_.set_constant(
                            expression,
                            static_cast<std::uint64_t>(
                                text->empty() ? 0 : static_cast<unsigned char>(text->front())));
                    } else if (text != nullptr) {
                        program_.set_constant(expression, *text);
                    }
                }
            },
            literal->value);
        return;
    }
    if (const auto* name = std::get_if<ast::NameExpression>(&expression.node)) {
        const sema::Symbol* symbol = model_.resolved(name->name);
        if (symbol == nullptr || !is_constant(*symbol)) {
            return;
        }
        // Only a VAR CONSTANT folds; its initial value was typed with its declaration.
        const ast::Expression& initial =
            *std::get<ast::ExpressionPtr>(symbol->variable->initial_value->value);
        if (program_.is_constant(*symbol->variable)) {
            if (const Constant* value = program_.constant_of(initial)) {
                program_.set_constant(expression, *value);
            }
        }
        return;
    }
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        const Constant* operand = program_.constant_of(*unary->operand);
        if (operand == nullptr || unary->op == ast::UnaryOperator::Plus) {
            if (operand != nullptr) {
                program_.set_constant(expression, *operand);
            }
            return;
        }
        if (unary->op == ast::UnaryOperator::Not) {
            if (const bool* b = std::get_if<bool>(operand)) {
                program_.set_constant(expression, !*b);
            }
            return;
        }
        if (const auto* i = std::get_if<std::int64_t>(operand)) {
            program_.set_constant(expression,
                                  static_cast<std::int64_t>(0 - static_cast<std::uint64_t>(*i)));
        } else if (const auto* d = std::get_if<double>(operand)) {
            program_.set_constant(expression, -*d);
        }
    }
}

} // namespace eposp::compiler::types
