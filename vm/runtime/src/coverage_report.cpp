#include "eposp/vm/coverage_report.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::vm {

std::size_t PouCoverage::lines_hit() const {
    return static_cast<std::size_t>(std::count_if(
        lines.begin(), lines.end(), [](const auto& line) { return line.second > 0; }));
}

std::size_t PouCoverage::branch_outcomes() const {
    std::size_t count = 0;
    for (const auto& [point, taken] : branches) {
        count += taken.size();
    }
    return count;
}

std::size_t PouCoverage::branch_outcomes_taken() const {
    std::size_t count = 0;
    for (const auto& [point, taken] : branches) {
        count += static_cast<std::size_t>(std::count_if(
            taken.begin(), taken.end(), [](std::uint64_t times) { return times > 0; }));
    }
    return count;
}

void CoverageReport::merge(const CoverageReport& other) {
    for (const auto& [name, theirs] : other.pous) {
        PouCoverage& ours = pous[name];
        ours.calls += theirs.calls;
        for (const auto& [line, times] : theirs.lines) {
            ours.lines[line] += times;
        }
        for (const auto& [point, taken] : theirs.branches) {
            auto& sum = ours.branches[point];
            if (sum.size() < taken.size()) {
                sum.insert(sum.end(), taken.size() - sum.size(), 0);
            }
            for (std::size_t outcome = 0; outcome < taken.size(); ++outcome) {
                sum[outcome] += taken[outcome];
            }
        }
    }
}

std::string coverage_summary(const CoverageReport& report) {
    std::string text;
    for (const auto& [name, pou] : report.pous) {
        const std::size_t hit = pou.lines_hit();
        const std::string percent =
            pou.lines.empty() ? "-"
                              : fmt::format("{:.1f}%", 100.0 * static_cast<double>(hit) /
                                                           static_cast<double>(pou.lines.size()));
        text += fmt::format("{}: lines {}/{} ({}), branches {}/{}\n", name, hit, pou.lines.size(),
                            percent, pou.branch_outcomes_taken(), pou.branch_outcomes());
    }
    return text;
}

} // namespace eposp::vm
