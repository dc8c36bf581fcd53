// The test recorder: TcUnit's model of tests that run cycle after cycle, fed with the calls an
// ST suite makes, in virtual time.
#include "eposp/plctest/test_recorder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::plctest {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;
using testing::ElementsAre;
using testing::Field;

core::TimePoint at(core::Duration d) {
    return core::TimePoint(d);
}

CallSite site(std::uint64_t key, std::uint32_t line) {
    return {key, {"suite.st", line}};
}

std::function<std::string()> says(std::string text) {
    return [text] {
        return text;
    };
}

TEST(TestRecorder, TestPassesWhenFinishedWithoutFailedAssertions) {
    TestRecorder recorder({});
    EXPECT_TRUE(recorder.begin_test("Adds", site(1, 3), at(seconds(0))));
    EXPECT_TRUE(recorder.check(true, site(2, 4), says("never asked")));
    EXPECT_TRUE(recorder.finish_test(at(seconds(0))));
    recorder.end_cycle(at(seconds(0)));
    EXPECT_TRUE(recorder.done());
    const auto results = recorder.results();
    ASSERT_EQ(results.size(), 1U);
    EXPECT_EQ(results[0].outcome, Outcome::Passed);
    EXPECT_EQ(results[0].place.line, 3U);
}

TEST(TestRecorder, FailedAssertionFailsItsTestWithItsPlaceAndText) {
    TestRecorder recorder({});
    recorder.begin_test("Adds", site(1, 3), at(seconds(0)));
    EXPECT_FALSE(recorder.check(false, site(2, 4), says("expected 5, got 7: sum")));
    recorder.finish_test(at(seconds(0)));
    const auto results = recorder.results();
    EXPECT_EQ(results[0].outcome, Outcome::Failed);
    ASSERT_EQ(results[0].failures.size(), 1U);
    EXPECT_EQ(results[0].failures[0].place.line, 4U);
    EXPECT_EQ(results[0].failures[0].text, "expected 5, got 7: sum");
}

TEST(TestRecorder, MultiCycleTestRunsUntilTestFinishedAndTakesItsMachineTime) {
    TestRecorder recorder({});
    for (int cycle = 0; cycle < 5; ++cycle) {
        EXPECT_TRUE(recorder.begin_test("Slow", site(1, 3), at(milliseconds(cycle))));
        if (cycle == 4) {
            recorder.finish_test(at(milliseconds(cycle)));
        }
        EXPECT_EQ(recorder.done(), cycle == 4);
        recorder.end_cycle(at(milliseconds(cycle)));
    }
    EXPECT_EQ(recorder.results()[0].machine_time, milliseconds(4));
    // Once finished, TEST() says so and its assertions count for nothing.
    EXPECT_FALSE(recorder.begin_test("Slow", site(1, 3), at(milliseconds(5))));
    recorder.check(false, site(2, 4), says("ignored"));
    EXPECT_EQ(recorder.results()[0].outcome, Outcome::Passed);
}

TEST(TestRecorder, AssertionFailingInEveryCycleIsReportedOnce) {
    TestRecorder recorder({});
    for (int cycle = 0; cycle < 3; ++cycle) {
        recorder.begin_test("Slow", site(1, 3), at(milliseconds(cycle)));
        recorder.check(false, site(2, 4), says("expected TRUE, got FALSE"));
        recorder.end_cycle(at(milliseconds(cycle)));
    }
    EXPECT_EQ(recorder.results()[0].failures.size(), 1U);
}

TEST(TestRecorder, DisabledTestIsSkippedAndItsAssertionsIgnored) {
    TestRecorder recorder({});
    EXPECT_FALSE(recorder.begin_test("disabled_Flaky", site(1, 3), at(seconds(0))));
    recorder.check(false, site(2, 4), says("ignored"));
    EXPECT_FALSE(recorder.finish_test(at(seconds(0))));
    EXPECT_TRUE(recorder.begin_test("Other", site(3, 6), at(seconds(0))));
    recorder.finish_test(at(seconds(0)));
    EXPECT_THAT(recorder.results(), ElementsAre(Field(&TestResult::outcome, Outcome::Skipped),
                                                Field(&TestResult::outcome, Outcome::Passed)));
    EXPECT_FALSE(recorder.misuse());
}

TEST(TestRecorder, TestNotSelectedIsNeitherRunNorReported) {
    TestRecorder recorder({.selected = [](std::string_view name) {
        return name == "Kept";
    }});
    EXPECT_FALSE(recorder.begin_test("Dropped", site(1, 3), at(seconds(0))));
    recorder.check(false, site(2, 4), says("ignored"));
    recorder.end_cycle(at(seconds(0)));
    EXPECT_TRUE(recorder.done());
    EXPECT_TRUE(recorder.results().empty());
    EXPECT_FALSE(recorder.misuse());
}

TEST(TestRecorder, TestPastItsTimeoutFails) {
    TestRecorder recorder({.timeout = milliseconds(10)});
    for (int cycle = 0; cycle <= 10; ++cycle) {
        recorder.begin_test("Never", site(1, 3), at(milliseconds(cycle)));
        recorder.end_cycle(at(milliseconds(cycle)));
    }
    EXPECT_TRUE(recorder.done());
    const auto results = recorder.results();
    ASSERT_EQ(results[0].failures.size(), 1U);
    EXPECT_EQ(results[0].failures[0].text,
              "did not finish within T#10ms of machine time (TEST_FINISHED() ends a test)");
    EXPECT_EQ(results[0].failures[0].place.line, 3U);
}

TEST(TestRecorder, WaitUntilHoldsFromTheFirstCycleItsConditionDoes) {
    TestRecorder recorder({});
    std::vector<bool> seen;
    for (int cycle = 0; cycle < 4; ++cycle) {
        recorder.begin_test("Waits", site(1, 3), at(milliseconds(cycle)));
        seen.push_back(
            recorder.wait_until(cycle == 2, seconds(1), site(2, 4), at(milliseconds(cycle))));
        recorder.end_cycle(at(milliseconds(cycle)));
    }
    EXPECT_THAT(seen, ElementsAre(false, false, true, true));
    EXPECT_EQ(recorder.results()[0].outcome, Outcome::Passed);
}

TEST(TestRecorder, WaitUntilTimingOutFailsAndEndsTheTest) {
    TestRecorder recorder({});
    for (int cycle = 0; cycle <= 5; ++cycle) {
        recorder.begin_test("Waits", site(1, 3), at(milliseconds(cycle)));
        recorder.wait_until(false, milliseconds(5), site(2, 4), at(milliseconds(cycle)));
        recorder.end_cycle(at(milliseconds(cycle)));
    }
    EXPECT_TRUE(recorder.done());
    const auto results = recorder.results();
    ASSERT_EQ(results[0].failures.size(), 1U);
    EXPECT_EQ(results[0].failures[0].text,
              "WAIT_UNTIL timed out: the condition did not hold within T#5ms");
    EXPECT_EQ(results[0].failures[0].place.line, 4U);
    EXPECT_EQ(results[0].machine_time, milliseconds(5));
}

TEST(TestRecorder, AdvanceTimeHoldsOnceItsDurationHasPassed) {
    TestRecorder recorder({});
    std::vector<bool> seen;
    for (int cycle = 0; cycle < 4; ++cycle) {
        recorder.begin_test("Waits", site(1, 3), at(milliseconds(10 + cycle)));
        seen.push_back(
            recorder.advance_time(milliseconds(2), site(2, 4), at(milliseconds(10 + cycle))));
        recorder.end_cycle(at(milliseconds(10 + cycle)));
    }
    EXPECT_THAT(seen, ElementsAre(false, false, true, true));
}

TEST(TestRecorder, WaitsOfTwoTestsAtOneCallSiteAreSeparate) {
    TestRecorder recorder({});
    recorder.begin_test("First", site(1, 3), at(milliseconds(0)));
    recorder.advance_time(milliseconds(2), site(9, 20), at(milliseconds(0)));
    recorder.begin_test("Second", site(2, 4), at(milliseconds(0)));
    recorder.end_cycle(at(milliseconds(0)));
    recorder.begin_test("First", site(1, 3), at(milliseconds(3)));
    EXPECT_TRUE(recorder.advance_time(milliseconds(2), site(9, 20), at(milliseconds(3))));
    recorder.begin_test("Second", site(2, 4), at(milliseconds(3)));
    EXPECT_FALSE(recorder.advance_time(milliseconds(2), site(9, 20), at(milliseconds(3))));
}

TEST(TestRecorder, AssertionOutsideATestIsAMisuse) {
    TestRecorder recorder({});
    recorder.check(false, site(2, 7), says("x"));
    ASSERT_TRUE(recorder.misuse());
    EXPECT_EQ(recorder.misuse()->place.line, 7U);
    EXPECT_EQ(recorder.misuse()->text, "an assertion outside a test: call TEST('name') before it");
}

TEST(TestRecorder, SameTestNameTwiceInOneCycleIsAMisuse) {
    TestRecorder recorder({});
    recorder.begin_test("Twin", site(1, 3), at(seconds(0)));
    recorder.begin_test("Twin", site(2, 9), at(seconds(0)));
    ASSERT_TRUE(recorder.misuse());
    EXPECT_EQ(recorder.misuse()->place.line, 9U);
}

TEST(TestRecorder, StopFailsEveryRunningTest) {
    TestRecorder recorder({});
    recorder.begin_test("A", site(1, 3), at(seconds(0)));
    recorder.finish_test(at(seconds(0)));
    recorder.begin_test("B", site(2, 5), at(seconds(0)));
    recorder.stop({{"suite.st", 6}, "division by zero in Suite at line 6"}, at(seconds(0)));
    EXPECT_TRUE(recorder.done());
    EXPECT_THAT(recorder.results(), ElementsAre(Field(&TestResult::outcome, Outcome::Passed),
                                                Field(&TestResult::outcome, Outcome::Failed)));
}

} // namespace
} // namespace eposp::plctest
