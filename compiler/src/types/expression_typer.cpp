// The typing pass's core (expression_typer.hpp): an expression typed where a value of a given
// type is expected, and the dispatch over the kinds of expression to the files that type them:
// operand_typing.cpp, operator_typing.cpp, call_typing.cpp (standard functions in
// standard_function_typing.cpp); declarations, statements and configurations have theirs.

#include "expression_typer.hpp"

#include "constant_folder.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::compiler::types {

namespace {

/// The integer literal without a type prefix that `expression` is (negated or not); null if
/// it is none.
const ast::IntegerLiteral* integer_literal(const ast::Expression& expression) {
    const ast::Expression* inner = &expression;
    bool negative = false;
    while (const auto* unary = std::get_if<ast::UnaryExpression>(&inner->node)) {
        if (unary->op == ast::UnaryOperator::Not) {
            return nullptr;
        }
        negative = negative != (unary->op == ast::UnaryOperator::Negate);
        inner = unary->operand.get();
    }
    const auto* literal = std::get_if<ast::LiteralExpression>(&inner->node);
    const auto* integer =
        literal != nullptr ? std::get_if<ast::IntegerLiteral>(&literal->value) : nullptr;
    return integer != nullptr && !integer->type && !negative ? integer : nullptr;
}

} // namespace

/// Why a value of `actual` cannot be stored where `target` is expected (`what`).
std::string mismatch(const char* what, const sema::Type& actual, const sema::Type& target) {
    if (std::string_view(what) == "a CASE label") {
        return fmt::format("a CASE label must be a value of {}", target.name);
    }
    if (std::string_view(what) == "an initial value" && target.kind == sema::TypeKind::Enum) {
        return fmt::format("the initial value must be a value of {}", target.name);
    }
    return fmt::format("a {} value cannot be used as {}{}", actual.name, target.name,
                       actual.kind == sema::TypeKind::Elementary &&
                               target.kind == sema::TypeKind::Elementary
                           ? fmt::format(" (convert it with {}_TO_{})", actual.name, target.name)
                           : "");
}

bool numeric_context(const sema::Type* type) {
    return type != nullptr && type->kind == sema::TypeKind::Elementary &&
           (sema::is_numeric(*type) || sema::is_bit_string(*type));
}

bool is_untyped_literal(const ast::Expression& expression) {
    if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
        return unary->op != ast::UnaryOperator::Not && is_untyped_literal(*unary->operand);
    }
    const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node);
    if (literal == nullptr) {
        return false;
    }
    if (const auto* integer = std::get_if<ast::IntegerLiteral>(&literal->value)) {
        return !integer->type;
    }
    const auto* real = std::get_if<ast::RealLiteral>(&literal->value);
    return real != nullptr && !real->type;
}

bool is_context_literal(const ast::Expression& expression) {
    if (is_untyped_literal(expression)) {
        return true;
    }
    const auto* literal = std::get_if<ast::LiteralExpression>(&expression.node);
    return literal != nullptr && (std::holds_alternative<ast::StringLiteral>(literal->value) ||
                                  std::holds_alternative<ast::NullLiteral>(literal->value));
}

ExpressionTyper::ExpressionTyper(TypedProgram& program, const sema::SemanticModel& model,
                                 Diagnostics& diagnostics)
    : program_(program), model_(model), diagnostics_(diagnostics) {}

const sema::Type* ExpressionTyper::fail(DiagnosticCode code, const SourceRange& range,
                                        std::string message) {
    diagnostics_.error(code, range, std::move(message));
    return nullptr;
}

void ExpressionTyper::condition(const ast::Expression& expression) {
    expect(expression, elementary(E::Bool), "a condition");
}

void ExpressionTyper::expect(const ast::Expression& expression, const sema::Type& target,
                             const char* what) {
    const sema::Type* actual = type(expression, &target);
    if (actual == nullptr) {
        return;
    }
    const sema::Type& to = program_.types().unranged(target);
    const sema::Type& from = program_.types().unranged(*actual);
    if (sema::converts_implicitly(from, to) || sema::conforms(*actual, target)) {
        return;
    }
    if (const auto* integer = integer_literal(expression);
        integer != nullptr && sema::is_integer(to) && std::string_view(what) != "a CASE label") {
        diagnostics_.error(DiagnosticCode::E0311, expression.range,
                           fmt::format("the value {}{} does not fit in {}",
                                       integer->negative ? "-" : "", integer->magnitude, to.name));
        return;
    }
    // An initial value is a constant of the variable's type (an enumeration value is its
    // number where an integer is expected).
    if (std::string_view(what) == "an initial value" && actual->kind == sema::TypeKind::Enum &&
        sema::is_integer(to)) {
        return;
    }
    // A value of another type is E0301 also as an initial value (figure 11, the catalogue):
    // `x : REAL := kDint` names both types, where E0313 said it was no constant.
    diagnostics_.error(DiagnosticCode::E0301, expression.range, mismatch(what, *actual, target));
}

void ExpressionTyper::store(const ast::Expression& expression, const sema::Type& target,
                            const char* what) {
    expect(expression, target, what);
    program_.add_store({&expression, &target, current_});
}

const sema::Type* ExpressionTyper::type(const ast::Expression& expression,
                                        const sema::Type* expected) {
    const sema::Type* result = std::visit(
        [&](const auto& node) -> const sema::Type* {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::LiteralExpression>) {
                return literal(expression, node.value, expected);
            } else if constexpr (std::is_same_v<T, ast::NameExpression>) {
                return name(expression, node);
            } else if constexpr (std::is_same_v<T, ast::MemberExpression>) {
                return member(expression, node);
            } else if constexpr (std::is_same_v<T, ast::BitAccessExpression>) {
                const sema::Type* word = type(*node.object, nullptr);
                if (word != nullptr && !sema::is_bit_string(*word) && !sema::is_integer(*word)) {
                    return fail(DiagnosticCode::E0304, expression.range,
                                fmt::format("bit access needs a bit string, not {}", word->name));
                }
                if (word != nullptr && node.bit >= word->size * 8) {
                    return fail(DiagnosticCode::E0105, expression.range,
                                fmt::format("{} has no bit {}", word->name, node.bit));
                }
                return &elementary(E::Bool);
            } else if constexpr (std::is_same_v<T, ast::IndexExpression>) {
                return index(expression, node);
            } else if constexpr (std::is_same_v<T, ast::DereferenceExpression>) {
                const sema::Type* reference = type(*node.reference, nullptr);
                if (reference != nullptr && (reference->kind != sema::TypeKind::Reference ||
                                             reference->element == nullptr)) {
                    return fail(DiagnosticCode::E0304, expression.range,
                                fmt::format("'^' needs a reference, not {}", reference->name));
                }
                return reference != nullptr ? reference->element : nullptr;
            } else if constexpr (std::is_same_v<T, ast::ReferenceExpression>) {
                const sema::Type* target = type(*node.target, nullptr);
                return target != nullptr ? &program_.types().reference(target) : nullptr;
            } else if constexpr (std::is_same_v<T, ast::CallExpression>) {
                const bool statement = statement_call_ == &expression;
                statement_call_ = nullptr;
                const sema::Type* value = call(expression, node, expected);
                if (value == nullptr && !statement && program_.call_target(expression) != nullptr) {
                    return fail(DiagnosticCode::E0309, expression.range, "this call has no value");
                }
                return value;
            } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                return unary(expression, node, expected);
            } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                return binary(expression, node, expected);
            } else {
                return &address_type(node.address);
            }
        },
        expression.node);
    if (result != nullptr) {
        program_.set_type(expression, *result);
        if (auto constant = program_.constants().value(expression, *result)) {
            record_constant(expression, std::move(*constant));
        }
    }
    return result;
}

void ExpressionTyper::record_constant(const ast::Expression& expression, Constant value) {
    program_.set_constant(expression, std::move(value));
    // Through the operands (a wrapped value divided by 2 is still wrong), but not through a
    // CONSTANT, whose own declaration refuses its value.
    const auto operand_wraps = [&]() {
        if (const auto* unary = std::get_if<ast::UnaryExpression>(&expression.node)) {
            return program_.wraps(*unary->operand);
        }
        if (const auto* binary = std::get_if<ast::BinaryExpression>(&expression.node)) {
            return program_.wraps(*binary->left) || program_.wraps(*binary->right);
        }
        const auto* call = std::get_if<ast::CallExpression>(&expression.node);
        return call != nullptr &&
               std::ranges::any_of(call->arguments, [&](const ast::Argument& argument) {
                   return program_.wraps(*argument.value);
               });
    };
    program_.set_wraps(expression, program_.constants().wraps(expression) || operand_wraps());
}

} // namespace eposp::compiler::types
