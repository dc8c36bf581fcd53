#include "coverage_counters.hpp"

#include <algorithm>
#include <limits>
#include <optional>

namespace eposp::vm::detail {
namespace {

constexpr std::uint32_t kNowhere = std::numeric_limits<std::uint32_t>::max();

bool is_jump_table(Opcode op) {
    return opcode_info(op).b.field == Field::JumpTable;
}

// A branch point: a jump table (one outcome per entry and one past its end), or a conditional
// jump, i.e. any jump but Jmp (jumped, fell through).
std::size_t outcome_count(const Image& image, const Instruction& ins) {
    if (is_jump_table(ins.opcode)) {
        return image.jump_tables[ins.b].targets.size() + 1;
    }
    return ins.opcode != Opcode::Jmp && branch_target(ins) ? 2 : 0;
}

std::uint32_t outcome_target(const Image& image, std::uint32_t at, std::size_t outcome) {
    const Instruction& ins = image.code[at];
    if (is_jump_table(ins.opcode)) {
        const auto& targets = image.jump_tables[ins.b].targets;
        return outcome < targets.size() ? targets[outcome] : ins.c;
    }
    return outcome == 0 ? *branch_target(ins) : at + 1;
}

// The instruction whose counts instruction `at` of POU `pou` adds to: itself, or in a body
// copied in place of a call the callee's instruction it copies (run_end.cpp's rule), followed
// through copies within copies. kNowhere for a cycle of copies, which no compile makes.
std::uint32_t home_of(const Image& image, std::uint32_t pou, std::uint32_t at) {
    for (std::size_t depth = 0; depth <= image.pous.size(); ++depth) {
        const auto& inlined = image.pous[pou].inlined;
        const auto call = std::find_if(inlined.begin(), inlined.end(),
                                       [at](const auto& c) { return c.begin <= at && at < c.end; });
        if (call == inlined.end()) {
            return at;
        }
        pou = call->callee;
        at = image.pous[pou].code_begin + (at - call->begin);
    }
    return kNowhere;
}

// How often control entered instructions [begin, end) at `begin` from outside: the runs of
// `begin` less the jumps back to it from inside (a loop at the top of a body). Instructions in
// `skip` (the copies of callees in a POU, whose counts went to their callees) are not looked at.
std::uint64_t entries(const Image& image, const CoverageCounters& counts, std::uint32_t begin,
                      std::uint32_t end, const std::vector<InlinedCall>& skip) {
    std::uint64_t jumps_back = 0;
    for (std::uint32_t at = begin; at < end; ++at) {
        if (std::any_of(skip.begin(), skip.end(),
                        [at](const auto& c) { return c.begin <= at && at < c.end; })) {
            continue;
        }
        const Instruction& ins = image.code[at];
        if (ins.opcode == Opcode::Jmp && ins.a == begin) {
            jumps_back += counts.executed[at];
        }
        const std::size_t outcomes = outcome_count(image, ins);
        for (std::size_t outcome = 0; outcome < outcomes; ++outcome) {
            if (outcome_target(image, at, outcome) == begin) {
                jumps_back += counts.outcomes[counts.first_outcome[at] + outcome];
            }
        }
    }
    const std::uint64_t runs = counts.executed[begin];
    return runs > jumps_back ? runs - jumps_back : 0;
}

// The counters with each copied instruction's counts added to the instruction it copies.
CoverageCounters folded(const Image& image, const CoverageCounters& counts) {
    CoverageCounters sums(image);
    for (std::uint32_t pou = 0; pou < image.pous.size(); ++pou) {
        for (auto at = image.pous[pou].code_begin; at < image.pous[pou].code_end; ++at) {
            const std::uint32_t home = home_of(image, pou, at);
            if (home == kNowhere) {
                continue;
            }
            sums.executed[home] += counts.executed[at];
            const std::size_t outcomes = outcome_count(image, image.code[at]);
            if (outcomes != 0 && outcomes == outcome_count(image, image.code[home])) {
                for (std::size_t outcome = 0; outcome < outcomes; ++outcome) {
                    sums.outcomes[sums.first_outcome[home] + outcome] +=
                        counts.outcomes[counts.first_outcome[at] + outcome];
                }
            }
        }
    }
    return sums;
}

PouCoverage pou_coverage(const Image& image, const Pou& pou, const CoverageCounters& counts,
                         const CoverageCounters& sums) {
    PouCoverage coverage;
    coverage.calls = entries(image, sums, pou.code_begin, pou.code_end, pou.inlined);
    const auto note_line = [&coverage](std::uint32_t line, std::uint64_t times) {
        auto& count = coverage.lines[line];
        count = std::max(count, times);
    };
    std::map<std::uint32_t, std::uint32_t> blocks_on_line;
    std::uint32_t line = 0;
    auto entry = pou.lines.begin();
    auto call = pou.inlined.begin();
    for (auto at = pou.code_begin; at < pou.code_end; ++at) {
        for (; entry != pou.lines.end() && entry->instruction <= at; ++entry) {
            line = entry->line;
        }
        while (call != pou.inlined.end() && call->end <= at) {
            ++call;
        }
        if (line == 0) {
            continue; // before the first line entry: no source to count it for
        }
        if (call != pou.inlined.end() && call->begin <= at) {
            // A callee's body copied here: its lines count for the callee, and the call's
            // line is executed as often as the copy is entered.
            if (at == call->begin) {
                note_line(line, entries(image, counts, call->begin, call->end, {}));
            }
            continue;
        }
        note_line(line, sums.executed[at]);
        const std::size_t outcomes = outcome_count(image, image.code[at]);
        if (outcomes != 0) {
            const auto first = sums.outcomes.begin() + sums.first_outcome[at];
            coverage.branches[BranchPoint{line, blocks_on_line[line]++}].assign(
                first, first + static_cast<std::ptrdiff_t>(outcomes));
        }
    }
    return coverage;
}

} // namespace

CoverageCounters::CoverageCounters(const Image& image)
    : executed(image.code.size()), first_outcome(image.code.size()) {
    std::uint32_t slots = 0;
    for (std::size_t at = 0; at < image.code.size(); ++at) {
        first_outcome[at] = slots;
        slots += static_cast<std::uint32_t>(outcome_count(image, image.code[at]));
    }
    outcomes.resize(slots);
}

CoverageReport coverage_report(const Image& image, const CoverageCounters& counters) {
    const CoverageCounters sums = folded(image, counters);
    CoverageReport report;
    for (const Pou& pou : image.pous) {
        if (!pou.lines.empty()) {
            report.pous[pou.name] = pou_coverage(image, pou, counters, sums);
        }
    }
    return report;
}

} // namespace eposp::vm::detail
