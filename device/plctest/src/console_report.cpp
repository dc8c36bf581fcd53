#include "eposp/plctest/reports.hpp"

#include <chrono>
#include <fmt/format.h>

namespace eposp::plctest {
namespace {

std::string place_prefix(const SourcePlace& place) {
    if (place.file.empty()) {
        return {};
    }
    return place.line ? fmt::format("{}:{}: ", place.file, place.line) : place.file + ": ";
}

double seconds(core::Duration duration) {
    return std::chrono::duration<double>(duration).count();
}

} // namespace

std::string totals_line(const Totals& totals) {
    std::string line = fmt::format("{} passed, {} failed", totals.passed, totals.failed);
    if (totals.skipped) {
        line += fmt::format(", {} skipped", totals.skipped);
    }
    return line;
}

std::string console_report(const std::vector<SuiteResult>& suites) {
    std::string report;
    for (const SuiteResult& suite : suites) {
        if (suite.error) {
            report += fmt::format("{}{}: {}\n", place_prefix(suite.error->place), suite.name,
                                  suite.error->text);
            if (suite.tests.empty()) {
                continue;
            }
        }
        const Totals counts = totals({suite});
        report += fmt::format("{}: {} ({} s machine time, {:.3f} s wall time)\n", suite.name,
                              totals_line(counts), seconds(suite.machine_time), suite.wall_seconds);
        for (const TestResult& test : suite.tests) {
            for (const Failure& failure : test.failures) {
                report += fmt::format("{}{}.{}: {}\n", place_prefix(failure.place), suite.name,
                                      test.name, failure.text);
            }
        }
    }
    report += totals_line(totals(suites)) + "\n";
    return report;
}

} // namespace eposp::plctest
