#include "eposp/plctest/reports.hpp"

#include <chrono>
#include <fmt/format.h>

namespace eposp::plctest {
namespace {

// The length of the valid UTF-8 sequence at the start of `text`, 0 if it is not one.
std::size_t utf8_length(std::string_view text) {
    const auto lead = static_cast<unsigned char>(text[0]);
    const std::size_t length = lead < 0x80                   ? 1
                               : lead >= 0xC2 && lead < 0xE0 ? 2
                               : lead >= 0xE0 && lead < 0xF0 ? 3
                               : lead >= 0xF0 && lead < 0xF5 ? 4
                                                             : 0;
    if (length == 0 || length > text.size()) {
        return 0;
    }
    for (std::size_t i = 1; i < length; ++i) {
        if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            return 0;
        }
    }
    return length;
}

// XML 1.0 allows neither most control characters nor invalid UTF-8, and a message from a
// program may contain any byte: those are written as \xNN.
std::string escaped(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    while (!text.empty()) {
        const char c = text[0];
        const std::size_t length = utf8_length(text);
        if (length > 1) {
            out += text.substr(0, length);
            text.remove_prefix(length);
            continue;
        }
        text.remove_prefix(1);
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&apos;";
            break;
        case '\t':
        case '\n':
        case '\r':
            out += fmt::format("&#{};", static_cast<int>(c));
            break;
        default:
            if (length == 0 || static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
                out += fmt::format("\\x{:02X}", static_cast<unsigned char>(c));
            } else {
                out += c;
            }
        }
    }
    return out;
}

std::string seconds(core::Duration duration) {
    return fmt::format("{:.6f}", std::chrono::duration<double>(duration).count());
}

std::string failure_text(const Failure& failure) {
    if (failure.place.file.empty()) {
        return failure.text;
    }
    return fmt::format("{}:{}: {}", failure.place.file, failure.place.line, failure.text);
}

void write_test(std::string& xml, const SuiteResult& suite, const TestResult& test) {
    xml += fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.6f}\"",
                       escaped(test.name), escaped(suite.name), test.wall_seconds);
    if (!test.place.file.empty()) {
        xml += fmt::format(" file=\"{}\" line=\"{}\"", escaped(test.place.file), test.place.line);
    }
    xml += ">\n";
    if (test.outcome == Outcome::Skipped) {
        xml += "      <skipped message=\"disabled\"/>\n";
    }
    for (const Failure& failure : test.failures) {
        xml += fmt::format("      <failure message=\"{}\" type=\"assertion\">{}</failure>\n",
                           escaped(failure.text), escaped(failure_text(failure)));
    }
    xml += fmt::format("      <system-out>machine time: {} s</system-out>\n",
                       seconds(test.machine_time));
    xml += "    </testcase>\n";
}

void write_suite(std::string& xml, const SuiteResult& suite) {
    const Totals counts = totals({suite});
    xml += fmt::format("  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" "
                       "skipped=\"{}\" time=\"{:.6f}\"",
                       escaped(suite.name), suite.tests.size() + (suite.error ? 1 : 0),
                       counts.failed - (suite.error ? 1 : 0), suite.error ? 1 : 0, counts.skipped,
                       suite.wall_seconds);
    if (!suite.place.file.empty()) {
        xml += fmt::format(" file=\"{}\"", escaped(suite.place.file));
    }
    xml += ">\n";
    xml += "    <properties>\n";
    xml += fmt::format("      <property name=\"machine_time\" value=\"{}\"/>\n",
                       seconds(suite.machine_time));
    for (const TestResult& test : suite.tests) {
        xml += fmt::format("      <property name=\"{}.machine_time\" value=\"{}\"/>\n",
                           escaped(test.name), seconds(test.machine_time));
    }
    xml += "    </properties>\n";
    if (suite.error) {
        xml += fmt::format("    <testcase name=\"{}\" classname=\"{}\" time=\"{:.6f}\">\n",
                           escaped(suite.name), escaped(suite.name), suite.wall_seconds);
        xml += fmt::format("      <error message=\"{}\" type=\"suite\">{}</error>\n",
                           escaped(suite.error->text), escaped(failure_text(*suite.error)));
        xml += "    </testcase>\n";
    }
    for (const TestResult& test : suite.tests) {
        write_test(xml, suite, test);
    }
    xml += "  </testsuite>\n";
}

} // namespace

std::string junit_xml(const std::vector<SuiteResult>& suites) {
    const Totals sum = totals(suites);
    std::size_t tests = 0;
    std::size_t errors = 0;
    double wall = 0;
    for (const SuiteResult& suite : suites) {
        tests += suite.tests.size() + (suite.error ? 1 : 0);
        errors += suite.error ? 1 : 0;
        wall += suite.wall_seconds;
    }
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += fmt::format("<testsuites name=\"eposp test\" tests=\"{}\" failures=\"{}\" "
                       "errors=\"{}\" time=\"{:.6f}\">\n",
                       tests, sum.failed - errors, errors, wall);
    for (const SuiteResult& suite : suites) {
        write_suite(xml, suite);
    }
    xml += "</testsuites>\n";
    return xml;
}

} // namespace eposp::plctest
