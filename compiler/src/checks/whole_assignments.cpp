// E0412: a function block instance is not a value that can be assigned (IEC 61131-3 ed. 3,
// 6.5.2.2 instantiates it, 7.3.3.2 assigns variables of data types), and an ARRAY[*] has no size
// to copy until it runs: only its elements can be assigned.

#include "pou_checks.hpp"

namespace eposp::compiler::checks {

void check_whole_assignments(const PouUnderCheck& check) {
    for (const ast::Statement* statement : check.body.assignments()) {
        const auto& assignment = std::get<ast::AssignmentStatement>(statement->node);
        const sema::Type* type = check.program.type_of(*assignment.target);
        if (type == nullptr) {
            continue;
        }
        if (type->kind == sema::TypeKind::Instance) {
            check.diagnostics.error(DiagnosticCode::E0412, statement->range,
                                    "a function block instance cannot be assigned");
        } else if (type->conformant) {
            check.diagnostics.error(DiagnosticCode::E0412, statement->range,
                                    "an ARRAY[*] cannot be assigned as a whole, only its elements");
        }
    }
}

} // namespace eposp::compiler::checks
