#include "case_labels.hpp"

#include "../types/constant_folder.hpp"

namespace eposp::compiler::checks {

CaseLabels case_labels(types::TypedProgram& program, const ast::CaseStatement& node,
                       const sema::Type& selector) {
    CaseLabels labels;
    labels.unsigned64 = sema::scalar_of(selector) == vm::Scalar::U64;
    const auto fold = [&](const ast::Expression& bound) -> std::optional<std::int64_t> {
        if (!labels.unsigned64) {
            return program.constants().fold_integer(bound);
        }
        const auto bits = program.constants().fold_unsigned(bound);
        return bits ? std::optional(static_cast<std::int64_t>(*bits)) : std::nullopt;
    };
    for (const ast::CaseBranch& branch : node.branches) {
        for (const ast::CaseLabel& label : branch.labels) {
            const auto low = fold(*label.low);
            const auto high = label.high ? fold(*label.high) : low;
            if (low && high) {
                labels.ranges.push_back({&label, *low, *high});
            }
        }
    }
    return labels;
}

} // namespace eposp::compiler::checks
