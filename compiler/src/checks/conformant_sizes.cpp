// E0417: SIZEOF of an ARRAY[*]: the size of an array whose bounds the caller gives is known only
// when running (IEC 61131-3 ed. 3, 6.5.3), and SIZEOF is a constant; LOWER_BOUND and
// UPPER_BOUND read the bounds.

#include "pou_checks.hpp"

namespace eposp::compiler::checks {

void check_conformant_sizes(const PouUnderCheck& check) {
    for (const ast::Expression* call : check.body.calls()) {
        const ast::Expression& expression = *call;
        const types::CallTarget* target = check.program.call_target(expression);
        if (target == nullptr || target->kind != types::CallKind::StandardFunction ||
            target->name != "SIZEOF") {
            continue;
        }
        const auto arguments =
            types::standard_arguments(target->name, std::get<ast::CallExpression>(expression.node));
        const sema::Type* type = arguments.size() == 1 && arguments.front() != nullptr
                                     ? check.program.type_of(*arguments.front()->value)
                                     : nullptr;
        if (type != nullptr && type->conformant) {
            check.diagnostics.error(DiagnosticCode::E0417, expression.range,
                                    "the size of an ARRAY[*] is known only when running: use "
                                    "LOWER_BOUND and UPPER_BOUND");
        }
    }
}

} // namespace eposp::compiler::checks
