#include "eposp/compiler/ast/calling_pous.hpp"

#include <algorithm>
#include <cctype>

namespace eposp::compiler::ast {
namespace {

// IEC identifiers are ASCII letters, digits and underscores (ed. 3, 6.1.2).
bool same_name(std::string_view a, std::string_view b) {
    return std::ranges::equal(
        a, b, [](unsigned char x, unsigned char y) { return std::toupper(x) == std::toupper(y); });
}

/// Looks for a call of one function by its name through statements and expressions.
class CallFinder {
public:
    explicit CallFinder(std::string_view function) : function_(function) {}

    bool in(const StatementList& statements) const {
        return std::ranges::any_of(statements, [this](const Statement& s) { return in(s); });
    }

private:
    bool in(const Statement& statement) const {
        return std::visit([this](const auto& node) { return in_node(node); }, statement.node);
    }

    bool in(const ExpressionPtr& expression) const {
        return expression != nullptr &&
               std::visit([this](const auto& node) { return in_node(node); }, expression->node);
    }

    bool in_node(const AssignmentStatement& node) const {
        return in(node.target) || in(node.value);
    }
    bool in_node(const CallStatement& node) const { return in(node.call); }
    bool in_node(const IfStatement& node) const {
        return std::ranges::any_of(node.branches,
                                   [this](const ConditionalBlock& branch) {
                                       return in(branch.condition) || in(branch.body);
                                   }) ||
               in(node.else_body);
    }
    bool in_node(const CaseStatement& node) const {
        return in(node.selector) ||
               std::ranges::any_of(node.branches,
                                   [this](const CaseBranch& branch) {
                                       return std::ranges::any_of(branch.labels,
                                                                  [this](const CaseLabel& label) {
                                                                      return in(label.low) ||
                                                                             in(label.high);
                                                                  }) ||
                                              in(branch.body);
                                   }) ||
               in(node.else_body);
    }
    bool in_node(const ForStatement& node) const {
        return in(node.from) || in(node.to) || in(node.by) || in(node.body);
    }
    bool in_node(const WhileStatement& node) const { return in(node.condition) || in(node.body); }
    bool in_node(const RepeatStatement& node) const { return in(node.body) || in(node.until); }
    bool in_node(const ExitStatement&) const { return false; }
    bool in_node(const ContinueStatement&) const { return false; }
    bool in_node(const ReturnStatement&) const { return false; }
    bool in_node(const EmptyStatement&) const { return false; }

    bool in_node(const LiteralExpression&) const { return false; }
    bool in_node(const NameExpression&) const { return false; }
    bool in_node(const DirectAddressExpression&) const { return false; }
    bool in_node(const MemberExpression& node) const { return in(node.object); }
    bool in_node(const BitAccessExpression& node) const { return in(node.object); }
    bool in_node(const IndexExpression& node) const {
        return in(node.array) ||
               std::ranges::any_of(node.indices, [this](const ExpressionPtr& i) { return in(i); });
    }
    bool in_node(const DereferenceExpression& node) const { return in(node.reference); }
    bool in_node(const ReferenceExpression& node) const { return in(node.target); }
    bool in_node(const CallExpression& node) const {
        if (const auto* name = std::get_if<NameExpression>(&node.callee->node);
            name != nullptr && same_name(name->name.name, function_)) {
            return true;
        }
        return in(node.callee) ||
               std::ranges::any_of(node.arguments,
                                   [this](const Argument& argument) { return in(argument.value); });
    }
    bool in_node(const UnaryExpression& node) const { return in(node.operand); }
    bool in_node(const BinaryExpression& node) const { return in(node.left) || in(node.right); }

    std::string_view function_;
};

} // namespace

std::vector<CallingPou> pous_calling(const CompilationUnit& unit, std::string_view function) {
    const CallFinder finder(function);
    std::vector<CallingPou> found;
    for (const Pou& pou : unit.pous) {
        if (pou.kind != PouKind::Function && finder.in(pou.body)) {
            found.push_back({pou.name.name, pou.kind, unit.file, pou.range});
        }
    }
    return found;
}

} // namespace eposp::compiler::ast
