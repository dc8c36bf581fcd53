#pragma once

// The values of a CASE statement's labels, folded as the selector's type orders them.

#include "eposp/compiler/types/typed_program.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace eposp::compiler::checks {

/// One label's values, low to high; a ULINT or LWORD selector's as the bits of unsigned 64-bit
/// numbers (`unsigned64`), so that every value of the selector's type is a label.
struct CaseLabelRange {
    const ast::CaseLabel* label = nullptr;
    std::int64_t low = 0;
    std::int64_t high = 0;
};

struct CaseLabels {
    bool unsigned64 = false;
    std::vector<CaseLabelRange> ranges; // the labels that fold, in the order written

    /// a <= b in the selector's order.
    bool at_most(std::int64_t a, std::int64_t b) const {
        return unsigned64 ? static_cast<std::uint64_t>(a) <= static_cast<std::uint64_t>(b) : a <= b;
    }
};

/// The labels of `node`, whose selector has the type `selector`.
CaseLabels case_labels(types::TypedProgram& program, const ast::CaseStatement& node,
                       const sema::Type& selector);

} // namespace eposp::compiler::checks
