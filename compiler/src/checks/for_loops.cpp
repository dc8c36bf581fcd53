// E0402, E0403, E0404: the rules of a FOR loop (IEC 61131-3 ed. 3, 7.3.3.4.2): its control
// variable is an integer variable the POU writes directly (not a CONSTANT, not a VAR_IN_OUT),
// its body does not assign it, and a constant step is not 0 (the loop would never end) nor
// negative on an unsigned control variable.

#include "../types/constant_folder.hpp"
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
        if (control != nullptr && !is_local_integer(*control)) {
            check_.diagnostics.error(DiagnosticCode::E0403, node.control_variable.range,
                                     "the control variable of a FOR loop must be a local "
                                     "integer variable (7.3.3.4.2)");
            return;
        }
        const sema::Type* type = control != nullptr &&
                                         control->kind == sema::SymbolKind::Variable &&
                                         control->variable != nullptr
                                     ? check_.program.types().resolve(control->variable->type)
                                     : nullptr;
        if (type == nullptr || !sema::is_integer(check_.program.types().unranged(*type))) {
            return; // not a local integer: E0403, and the body is not looked at further
        }
        if (node.by) {
            const auto step = check_.program.constants().fold_integer(*node.by);
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

    // Whether `symbol` may control a FOR loop: an integer variable of the POU or a global one,
    // neither CONSTANT nor VAR_IN_OUT, or a function's result. A name of another kind, or a
    // VAR_EXTERNAL without its global, is an error of the names (E0204, E0208), not this one.
    bool is_local_integer(const sema::Symbol& symbol) {
        types::TypedProgram& program = check_.program;
        if (symbol.kind == sema::SymbolKind::ProgramInstance ||
            (symbol.kind == sema::SymbolKind::Pou && symbol.pou->kind == ast::PouKind::Program)) {
            return false; // a program instance (also its own name, CODESYS)
        }
        if (symbol.kind == sema::SymbolKind::Pou && symbol.pou == &check_.pou) {
            const sema::Type* result =
                symbol.pou->kind == ast::PouKind::Function && symbol.pou->return_type
                    ? program.types().resolve(*symbol.pou->return_type)
                    : nullptr;
            return result == nullptr || sema::is_integer(*result);
        }
        if (symbol.kind != sema::SymbolKind::Variable || symbol.variable == nullptr) {
            return true;
        }
        const sema::Symbol* declared = &symbol;
        if (symbol.section == ast::VarSectionKind::External ||
            (symbol.section == ast::VarSectionKind::Global && !declares(symbol.variable))) {
            declared = program.model().global().find(symbol.name);
            if (declared == nullptr || declared->kind != sema::SymbolKind::Variable ||
                declared->variable == nullptr) {
                return true;
            }
            if (program.is_constant(*symbol.variable)) {
                return false; // VAR_EXTERNAL CONSTANT
            }
        }
        const sema::Type* type = program.types().resolve(declared->variable->type);
        return type == nullptr ||
               (sema::is_integer(*type) && declared->section != ast::VarSectionKind::InOut &&
                !program.is_constant(*declared->variable));
    }
    // Whether the POU under check declares `declaration` itself (a PROGRAM's own VAR_GLOBAL).
    bool declares(const ast::VariableDeclaration* declaration) const {
        for (const ast::DeclarationSection& section : check_.pou.sections) {
            const auto* variables = std::get_if<ast::VarSection>(&section);
            if (variables != nullptr && !variables->variables.empty() &&
                declaration >= variables->variables.data() &&
                declaration < variables->variables.data() + variables->variables.size()) {
                return true;
            }
        }
        return false;
    }

    const PouUnderCheck& check_;
    std::vector<const sema::Symbol*> controls_; // of the enclosing FOR loops
};

} // namespace

void check_for_loops(const PouUnderCheck& check) {
    ForLoops(check).statements(check.pou.body);
}

} // namespace eposp::compiler::checks
