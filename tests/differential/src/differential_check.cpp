#include "eposp/differential/differential_check.hpp"

#include "eposp/differential/reducer.hpp"

#include <cctype>
#include <random>
#include <sstream>
#include <string_view>

namespace eposp::differential {
namespace {

/// The line a fault names ("... in Main at line 12"), or empty.
std::string fault_line(const std::string& fault) {
    // Not std::regex: g++ 12 warns inside <regex> at -O1 with the sanitizers.
    constexpr std::string_view kLine = "line ";
    for (auto at = fault.find(kLine); at != std::string::npos; at = fault.find(kLine, at + 1)) {
        auto end = at + kLine.size();
        while (end < fault.size() && std::isdigit(static_cast<unsigned char>(fault[end])) != 0) {
            ++end;
        }
        if (end > at + kLine.size()) {
            return fault.substr(at + kLine.size(), end - at - kLine.size());
        }
    }
    return {};
}

/// The first error message of a rejected program, without its location.
std::string first_error(const Verdict& verdict) {
    const std::string& errors = verdict.executions.front().errors;
    const auto at = errors.find("error:");
    return at == std::string::npos ? errors : errors.substr(at, errors.find('\n', at) - at);
}

bool same(const Execution& a, const Execution& b) {
    if (a.loaded != b.loaded || a.checksums != b.checksums || a.fault_scan != b.fault_scan) {
        return false;
    }
    // Where it faults: the same scan and, when both name one, the same line.
    const std::string line_a = fault_line(a.fault);
    const std::string line_b = fault_line(b.fault);
    return line_a.empty() || line_b.empty() || line_a == line_b;
}

} // namespace

std::string Verdict::describe() const {
    std::ostringstream out;
    for (std::size_t i = 0; i < executions.size(); ++i) {
        const Execution& e = executions[i];
        out << "  " << names[i] << ":";
        if (!e.loaded) {
            const auto at = e.errors.find("error");
            const std::string error = e.errors.substr(at == std::string::npos ? 0 : at);
            out << " did not load: " << error.substr(0, error.find('\n'));
        }
        for (const auto checksum : e.checksums) {
            out << " " << std::hex << checksum << std::dec;
        }
        if (e.fault_scan) {
            out << " fault in scan " << *e.fault_scan << ": " << e.fault;
        }
        out << "\n";
    }
    return out.str();
}

Verdict compare(const std::vector<Executor*>& executors, const std::string& source, int scans) {
    Verdict verdict;
    bool any_loaded = false;
    bool vm_rejects = false;
    for (Executor* executor : executors) {
        verdict.names.push_back(executor->name());
        verdict.executions.push_back(executor->run(source, scans));
        const Execution& e = verdict.executions.back();
        any_loaded = any_loaded || e.loaded;
        vm_rejects = vm_rejects || (!e.loaded && !executor->may_refuse());
        int group = static_cast<int>(verdict.classes.size());
        if (!e.loaded && executor->may_refuse()) {
            group = -1;
        } else {
            for (std::size_t j = 0; j < verdict.classes.size(); ++j) {
                if (verdict.classes[j] >= 0 && same(verdict.executions[j], e)) {
                    group = verdict.classes[j];
                    break;
                }
            }
        }
        verdict.classes.push_back(group);
    }
    if (vm_rejects && !any_loaded) {
        verdict.outcome = Verdict::Outcome::Invalid;
        return verdict;
    }
    for (std::size_t i = 0; i < verdict.classes.size(); ++i) {
        if (verdict.classes[i] != -1 && verdict.classes[i] != verdict.classes.front()) {
            verdict.outcome = Verdict::Outcome::Disagree;
        }
    }
    if (verdict.classes.front() == -1) {
        verdict.outcome = Verdict::Outcome::Invalid;
    }
    return verdict;
}

Finding check_seed(std::uint64_t seed, const GeneratorOptions& options,
                   const std::vector<Executor*>& executors, int scans, bool reduce_it) {
    std::mt19937_64 random(seed);
    GeneratedProgram program = generate_program(random, options);
    Finding finding{seed, {}, render(program.block), {}};
    finding.verdict = compare(executors, finding.program, scans);
    if (reduce_it && !finding.agree()) {
        const Verdict::Outcome outcome = finding.verdict.outcome;
        const std::vector<int> classes = finding.verdict.classes;
        const std::string error = first_error(finding.verdict);
        // The same disagreement (the same executors on each side), or the same rejection.
        const auto interesting = [&](const std::string& source) {
            const Verdict candidate = compare(executors, source, scans);
            return candidate.outcome == outcome && candidate.classes == classes &&
                   (outcome != Verdict::Outcome::Invalid || first_error(candidate) == error);
        };
        finding.reduced = render(reduce(std::move(program.block), interesting));
        finding.verdict = compare(executors, finding.reduced, scans);
    }
    return finding;
}

std::string describe(const Finding& finding) {
    std::ostringstream out;
    out << (finding.verdict.outcome == Verdict::Outcome::Invalid ? "INVALID PROGRAM" : "MISMATCH")
        << " seed " << finding.seed << "\n"
        << finding.verdict.describe()
        << (finding.reduced.empty() ? "program:\n" + finding.program
                                    : "reduced program:\n" + finding.reduced);
    return out.str();
}

} // namespace eposp::differential
