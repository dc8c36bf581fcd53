#include "eposp/plctest/lcov_writer.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <tuple>
#include <vector>

namespace eposp::plctest {
namespace {

struct Function {
    std::uint32_t line = 0;
    std::string name;
    std::uint64_t calls = 0;
};

/// What one source file's record shows: its POUs merged, lines and branch points by line (a
/// line shared by two POUs adds their counts and numbers their branch points on).
struct SourceRecord {
    std::vector<Function> functions;
    std::map<std::uint32_t, std::uint64_t> lines;
    std::map<std::uint32_t, std::vector<std::vector<std::uint64_t>>> branches;

    void add(const std::string& name, const vm::PouCoverage& pou) {
        if (!pou.lines.empty()) {
            functions.push_back({pou.lines.begin()->first, name, pou.calls});
        }
        for (const auto& [line, times] : pou.lines) {
            lines[line] += times;
        }
        for (const auto& [point, taken] : pou.branches) {
            branches[point.line].push_back(taken);
        }
    }
};

std::string sanitized(std::string_view name) {
    std::string text(name);
    std::replace_if(
        text.begin(), text.end(),
        [](char c) { return std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_'; }, '_');
    return text;
}

void append_record(std::string& out, const std::string& path, SourceRecord& record) {
    std::sort(record.functions.begin(), record.functions.end(),
              [](const Function& a, const Function& b) {
                  return std::tie(a.line, a.name) < std::tie(b.line, b.name);
              });
    out += fmt::format("SF:{}\n", path);
    std::size_t functions_hit = 0;
    for (const Function& function : record.functions) {
        out += fmt::format("FN:{},{}\n", function.line, function.name);
    }
    for (const Function& function : record.functions) {
        out += fmt::format("FNDA:{},{}\n", function.calls, function.name);
        functions_hit += function.calls > 0 ? 1 : 0;
    }
    out += fmt::format("FNF:{}\nFNH:{}\n", record.functions.size(), functions_hit);
    std::size_t outcomes = 0;
    std::size_t outcomes_taken = 0;
    for (const auto& [line, points] : record.branches) {
        for (std::size_t block = 0; block < points.size(); ++block) {
            const auto& taken = points[block];
            // "-": the branch point itself never ran (geninfo(1)).
            const bool reached = std::any_of(taken.begin(), taken.end(),
                                             [](std::uint64_t times) { return times > 0; });
            for (std::size_t outcome = 0; outcome < taken.size(); ++outcome) {
                out += fmt::format("BRDA:{},{},{},{}\n", line, block, outcome,
                                   reached ? std::to_string(taken[outcome]) : "-");
                ++outcomes;
                outcomes_taken += taken[outcome] > 0 ? 1 : 0;
            }
        }
    }
    out += fmt::format("BRF:{}\nBRH:{}\n", outcomes, outcomes_taken);
    std::size_t lines_hit = 0;
    for (const auto& [line, times] : record.lines) {
        out += fmt::format("DA:{},{}\n", line, times);
        lines_hit += times > 0 ? 1 : 0;
    }
    out += fmt::format("LF:{}\nLH:{}\nend_of_record\n", record.lines.size(), lines_hit);
}

} // namespace

std::string lcov_tracefile(const vm::CoverageReport& report,
                           const std::map<std::string, std::string>& sources,
                           std::string_view test_name) {
    std::map<std::string, SourceRecord> records;
    for (const auto& [name, pou] : report.pous) {
        if (const auto source = sources.find(name); source != sources.end()) {
            records[source->second].add(name, pou);
        }
    }
    std::string out;
    for (auto& [path, record] : records) {
        out += fmt::format("TN:{}\n", sanitized(test_name));
        append_record(out, path, record);
    }
    return out;
}

} // namespace eposp::plctest
