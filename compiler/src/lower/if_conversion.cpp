#include "if_conversion.hpp"

#include "eposp/compiler/sema/symbol.hpp"

#include <string>
#include <string_view>

namespace eposp::compiler::lower {
namespace {

// Both values are always computed, so each must stay small.
constexpr int kMaximumNodes = 8;

bool is_shift(std::string_view name) {
    const std::string folded = sema::fold_case(name);
    for (std::string_view shift : {"SHL", "SHR", "ROL", "ROR"}) {
        if (folded == sema::fold_case(shift)) {
            return true;
        }
    }
    return false;
}

/// Whether evaluating `expression` can neither trap, call anything with an effect, nor take
/// long: names, literals, member and bit reads, arithmetic without division, comparisons,
/// logic and the shifts. `nodes` counts what it costs.
bool cheap_and_pure(const ast::Expression& expression, int& nodes) {
    if (++nodes > kMaximumNodes) {
        return false;
    }
    return std::visit(
        [&](const auto& node) {
            using T = std::decay_t<decltype(node)>;
            if constexpr (std::is_same_v<T, ast::LiteralExpression> ||
                          std::is_same_v<T, ast::NameExpression>) {
                return true;
            } else if constexpr (std::is_same_v<T, ast::MemberExpression> ||
                                 std::is_same_v<T, ast::BitAccessExpression>) {
                return cheap_and_pure(*node.object, nodes);
            } else if constexpr (std::is_same_v<T, ast::UnaryExpression>) {
                return cheap_and_pure(*node.operand, nodes);
            } else if constexpr (std::is_same_v<T, ast::BinaryExpression>) {
                return node.op != ast::BinaryOperator::Divide &&
                       node.op != ast::BinaryOperator::Modulo &&
                       node.op != ast::BinaryOperator::Power && cheap_and_pure(*node.left, nodes) &&
                       cheap_and_pure(*node.right, nodes);
            } else if constexpr (std::is_same_v<T, ast::CallExpression>) {
                const auto* callee = std::get_if<ast::NameExpression>(&node.callee->node);
                if (callee == nullptr || !is_shift(callee->name.name) ||
                    node.arguments.size() != 2) {
                    return false;
                }
                for (const ast::Argument& argument : node.arguments) {
                    if (argument.kind != ast::Argument::Kind::Positional || argument.negated ||
                        !cheap_and_pure(*argument.value, nodes)) {
                        return false;
                    }
                }
                return true;
            } else {
                return false; // indexing and dereferencing can trap; the rest have effects
            }
        },
        expression.node);
}

/// The single plain assignment `list` consists of, or null.
const ast::AssignmentStatement* lone_assignment(const ast::StatementList& list) {
    return list.size() == 1 ? std::get_if<ast::AssignmentStatement>(&list.front().node) : nullptr;
}

} // namespace

std::optional<SelectForm> select_form(const ast::IfStatement& node) {
    if (node.branches.size() != 1) {
        return std::nullopt;
    }
    const auto* then = lone_assignment(node.branches.front().body);
    const auto* otherwise = lone_assignment(node.else_body);
    if (then == nullptr || (otherwise == nullptr && !node.else_body.empty())) {
        return std::nullopt;
    }
    const auto* target = std::get_if<ast::NameExpression>(&then->target->node);
    if (target == nullptr) {
        return std::nullopt;
    }
    if (otherwise != nullptr) {
        const auto* other = std::get_if<ast::NameExpression>(&otherwise->target->node);
        if (other == nullptr ||
            sema::fold_case(other->name.name) != sema::fold_case(target->name.name)) {
            return std::nullopt;
        }
    }
    // The branch form evaluates the right side of AND / OR only when it decides: the select
    // form evaluates everything, which is the same only where nothing can trap.
    const ast::Expression& condition = *node.branches.front().condition;
    const ast::Expression* otherwise_value =
        otherwise != nullptr ? otherwise->value.get() : nullptr;
    const ast::Expression* chosen = then->value.get();
    for (const ast::Expression* part : {&condition, chosen, otherwise_value}) {
        int nodes = 0;
        if (part != nullptr && !cheap_and_pure(*part, nodes)) {
            return std::nullopt;
        }
    }
    return SelectForm{&condition, then->target.get(), chosen, otherwise_value};
}

} // namespace eposp::compiler::lower
