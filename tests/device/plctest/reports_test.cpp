// The reports of `eposp test`: the console text and JUnit XML.
#include "eposp/plctest/reports.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::plctest {
namespace {

using std::chrono::milliseconds;
using testing::HasSubstr;

std::vector<SuiteResult> sample_run() {
    SuiteResult math{.name = "MathSuite", .place = {"math_test.st", 1}};
    math.tests.push_back({.name = "Adds", .place = {"math_test.st", 5}});
    math.tests.push_back(
        {.name = "Subtracts",
         .place = {"math_test.st", 9},
         .outcome = Outcome::Failed,
         .failures = {{{"math_test.st", 10}, "expected 5, got 7: the <sum> & \"more\""}},
         .machine_time = milliseconds(2000),
         .wall_seconds = 0.25});
    math.tests.push_back({.name = "disabled_Divides", .outcome = Outcome::Skipped});
    math.machine_time = milliseconds(2000);
    SuiteResult broken{.name = "Broken", .place = {"broken_test.st", 1}};
    broken.error = Failure{{"broken_test.st", 4}, "does not compile"};
    return {math, broken};
}

TEST(ConsoleReport, PrintsEachFailureWithFileLineSuiteAndTestThenTheTotals) {
    const std::string report = console_report(sample_run());
    EXPECT_THAT(report, HasSubstr("math_test.st:10: MathSuite.Subtracts: expected 5, got 7: the "
                                  "<sum> & \"more\"\n"));
    EXPECT_THAT(report, HasSubstr("broken_test.st:4: Broken: does not compile\n"));
    EXPECT_THAT(report, testing::EndsWith("\n1 passed, 2 failed, 1 skipped\n"));
}

TEST(ConsoleReport, TotalsLineNamesSkippedOnlyWhenAnyWere) {
    EXPECT_EQ(totals_line({3, 0, 0}), "3 passed, 0 failed");
    EXPECT_EQ(totals_line({3, 1, 2}), "3 passed, 1 failed, 2 skipped");
}

TEST(JunitXml, HasOneTestcasePerTestWithFailuresEscapedAndMachineTime) {
    const std::string xml = junit_xml(sample_run());
    EXPECT_THAT(xml, HasSubstr("<testsuites name=\"eposp test\" tests=\"4\" failures=\"1\" "
                               "errors=\"1\""));
    EXPECT_THAT(xml, HasSubstr("<testsuite name=\"MathSuite\" tests=\"3\" failures=\"1\" "
                               "errors=\"0\" skipped=\"1\""));
    EXPECT_THAT(xml, HasSubstr("<testcase name=\"Subtracts\" classname=\"MathSuite\" "
                               "time=\"0.250000\" file=\"math_test.st\" line=\"9\">"));
    EXPECT_THAT(xml, HasSubstr("message=\"expected 5, got 7: the &lt;sum&gt; &amp; "
                               "&quot;more&quot;\""));
    EXPECT_THAT(xml, HasSubstr("<system-out>machine time: 2.000000 s</system-out>"));
    EXPECT_THAT(xml, HasSubstr("<skipped message=\"disabled\"/>"));
    EXPECT_THAT(xml, HasSubstr("<error message=\"does not compile\" type=\"suite\">"
                               "broken_test.st:4: does not compile</error>"));
}

TEST(JunitXml, BytesThatAreNotUtf8OrAreControlCharactersAreWrittenAsEscapes) {
    SuiteResult suite{.name = "S"};
    suite.tests.push_back({.name = "T",
                           .outcome = Outcome::Failed,
                           .failures = {{{},
                                         std::string("a\x01"
                                                     "b\xFF"
                                                     "c\xC3\xA9")}}});
    const std::string xml = junit_xml({suite});
    EXPECT_THAT(xml, HasSubstr("message=\"a\\x01b\\xFFc\xC3\xA9\""));
}

} // namespace
} // namespace eposp::plctest
