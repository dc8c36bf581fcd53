#pragma once

#include "eposp/vm/coverage_report.hpp"
#include "eposp/vm/image.hpp"

#include <cstdint>
#include <vector>

namespace eposp::vm::detail {

/// What the interpreter counts while it records coverage, per instruction of the image: how
/// often it was dispatched, and for a branch point how often each outcome was taken. Turned
/// into lines and branches of POUs only when asked (coverage_report).
struct CoverageCounters {
    explicit CoverageCounters(const Image& image);

    std::vector<std::uint64_t> executed;
    /// Per instruction: where its outcomes start in `outcomes` (branch points only).
    std::vector<std::uint32_t> first_outcome;
    std::vector<std::uint64_t> outcomes;
};

/// The counts by POU and source line; an inlined copy's counts go to the callee's lines.
CoverageReport coverage_report(const Image& image, const CoverageCounters& counters);

} // namespace eposp::vm::detail
