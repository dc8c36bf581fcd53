// E0406: each value selects one branch of a CASE (IEC 61131-3 ed. 3, 7.3.3.3.3), so no two
// labels share a value.

#include "case_labels.hpp"
#include "pou_checks.hpp"

namespace eposp::compiler::checks {

void check_overlapping_case_labels(const PouUnderCheck& check) {
    for (const ast::Statement* statement : check.body.statements()) {
        const auto* node = std::get_if<ast::CaseStatement>(&statement->node);
        const sema::Type* type = node != nullptr ? check.program.type_of(*node->selector) : nullptr;
        if (type == nullptr || (!sema::is_integer(*type) && !sema::is_bit_string(*type) &&
                                type->kind != sema::TypeKind::Enum)) {
            continue; // no CASE, or a selector the typing stage refused
        }
        const CaseLabels labels = case_labels(check.program, *node, *type);
        for (std::size_t i = 0; i < labels.ranges.size(); ++i) {
            const CaseLabelRange& label = labels.ranges[i];
            for (std::size_t j = 0; j < i; ++j) {
                const CaseLabelRange& seen = labels.ranges[j];
                if (labels.at_most(label.low, seen.high) && labels.at_most(seen.low, label.high)) {
                    check.diagnostics.error(DiagnosticCode::E0406, label.label->range,
                                            "this CASE label overlaps an earlier one");
                }
            }
        }
    }
}

} // namespace eposp::compiler::checks
