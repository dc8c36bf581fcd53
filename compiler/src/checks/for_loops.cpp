// E0402, E0404: the rules of a FOR loop (IEC 61131-3 ed. 3, 7.3.3.4.2): its body does not
// assign the control variable, and a constant step is not 0 (the loop would never end) nor
// negative on an unsigned control variable.

#include "pou_checks.hpp"

#include <cstdint>
#include <type_traits>
#include <variant>
#include <vector>

namespace eposp::compiler::checks {
namespace {

class ForLoops {
public:
    explicit ForLoops(const PouUnderCheck& check) : check_(check) {}

    void statements(const ast::StatementList& list) {
        for (const ast::Statement& statement : list) {
            std::visit([&](const auto& node) { this->statement(node); }, statement.node);
        }
    }

private:
    void statement(const ast::AssignmentStatement& node) {
        const auto* name = std::get_if<ast::NameExpression>(&node.target->node);
        const sema::Symbol* symbol =
            name != nullptr ? check_.program.model().resolved(name->name) : nullptr;
        for (const sema::Symbol* control : controls_) {
            if (symbol != nullptr && symbol == control) {
                check_.diagnostics.error(DiagnosticCode::E0402, node.target->range,
                                         "the control variable of a FOR loop cannot be assigned "
                                         "in its body (IEC 61131-3 7.3.3.4.2)");
                return;
            }
        }
    }
    void statement(const ast::IfStatement& node) {
        for (const ast::ConditionalBlock& branch : node.branches) {
            statements(branch.body);
        }
        statements(node.else_body);
    }
    void statement(const ast::CaseStatement& node) {
        for (const ast::CaseBranch& branch : node.branches) {
            statements(branch.body);
        }
        statements(node.else_body);
    }
    void statement(const ast::ForStatement& node) {
        const sema::Symbol* control = check_.program.model().resolved(node.control_variable);
        const sema::Type* type = control != nullptr &&
                                         control->kind == sema::SymbolKind::Variable &&
                                         control->variable != nullptr
                                     ? check_.program.types().resolve(control->variable->type)
                                     : nullptr;
        if (type == nullptr || !sema::is_integer(check_.program.types().unranged(*type))) {
            return; // not a local integer: E0403, and the body is not looked at further
        }
        if (node.by) {
            const auto step = check_.program.types().fold_integer(*node.by);
            if (step && *step == 0) {
                check_.diagnostics.error(DiagnosticCode::E0404, node.by->range, "BY must not be 0");
                return;
            }
            // A step beyond INT is taken as computed, whose sign the loop tests when running.
            if (step && *step < 0 && *step >= INT16_MIN && !sema::is_signed(*type)) {
                check_.diagnostics.error(DiagnosticCode::E0404, node.by->range,
                                         "a negative step needs a signed control variable");
                return;
            }
        }
        controls_.push_back(control);
        statements(node.body);
        controls_.pop_back();
    }
    void statement(const ast::WhileStatement& node) { statements(node.body); }
    void statement(const ast::RepeatStatement& node) { statements(node.body); }
    template <typename Other>
    void statement(const Other&) {} // calls, EXIT, CONTINUE, RETURN, ';'

    const PouUnderCheck& check_;
    std::vector<const sema::Symbol*> controls_; // of the enclosing FOR loops
};

} // namespace

void check_for_loops(const PouUnderCheck& check) {
    ForLoops(check).statements(check.pou.body);
}

} // namespace eposp::compiler::checks
