#include "eposp/plctest/test_recorder.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

namespace eposp::plctest {
namespace {

bool is_disabled(std::string_view name) {
    constexpr std::string_view prefix = "disabled_";
    return name.size() >= prefix.size() &&
           std::equal(prefix.begin(), prefix.end(), name.begin(), [](char a, char b) {
               return a == std::tolower(static_cast<unsigned char>(b));
           });
}

} // namespace

std::string time_literal(core::Duration duration) {
    return "T#" + core::format_duration(duration);
}

TestRecorder::TestRecorder(Settings settings) : settings_(std::move(settings)) {}

double TestRecorder::wall_now() const {
    return settings_.wall_clock ? settings_.wall_clock() : 0.0;
}

TestRecorder::Test* TestRecorder::running_test() {
    if (!current_ || !tests_[*current_].running) {
        return nullptr;
    }
    return &tests_[*current_];
}

bool TestRecorder::begin_test(std::string_view name, const CallSite& site, core::TimePoint now) {
    outside_tests_ = false;
    began_any_ = true;
    const auto known = std::ranges::find(
        tests_, name, [](const Test& t) { return std::string_view(t.result.name); });
    if (known != tests_.end()) {
        current_ = static_cast<std::size_t>(known - tests_.begin());
        if (known->last_cycle == cycle_) {
            report_misuse(site.place, fmt::format("TEST('{}') is called twice in one cycle: the "
                                                  "tests of a suite need names of their own",
                                                  name));
        }
        known->last_cycle = cycle_;
        return known->running;
    }
    if (settings_.selected && !settings_.selected(name)) {
        current_.reset(); // its assertions count for nothing
        return false;
    }
    Test test;
    test.result.name = std::string(name);
    test.result.place = site.place;
    test.started = now;
    test.wall_started = wall_now();
    test.last_cycle = cycle_;
    if (is_disabled(name)) {
        test.result.outcome = Outcome::Skipped;
        test.running = false;
    }
    tests_.push_back(std::move(test));
    current_ = tests_.size() - 1;
    return tests_.back().running;
}

bool TestRecorder::finish_test(core::TimePoint now) {
    Test* test = running_test();
    if (!test) {
        return false;
    }
    end(*test, now);
    return true;
}

bool TestRecorder::check(bool passed, const CallSite& site,
                         const std::function<std::string()>& describe) {
    if (passed) {
        return true;
    }
    if (outside_tests_) {
        report_misuse(site.place, "an assertion outside a test: call TEST('name') before it");
        return false;
    }
    Test* test = running_test();
    if (!test || std::ranges::find(test->failed_sites, site.key) != test->failed_sites.end()) {
        return false; // a finished test's, or reported in an earlier cycle already
    }
    test->failed_sites.push_back(site.key);
    fail(*test, {site.place, describe()});
    return false;
}

bool TestRecorder::wait_until(bool condition, core::Duration timeout, const CallSite& site,
                              core::TimePoint now) {
    Test* test = running_test();
    if (!test) {
        if (outside_tests_) {
            report_misuse(site.place, "WAIT_UNTIL outside a test: call TEST('name') before it");
        }
        return false;
    }
    const auto [wait, first] = test->waits.try_emplace(site.key, now);
    if (condition || wait->second == core::TimePoint::max()) {
        wait->second = core::TimePoint::max(); // over: stays TRUE for the rest of the test
        return true;
    }
    if (now - wait->second >= timeout) {
        fail(*test, {site.place, fmt::format("WAIT_UNTIL timed out: the condition did not hold "
                                             "within {}",
                                             time_literal(timeout))});
        end(*test, now);
    }
    return false;
}

bool TestRecorder::advance_time(core::Duration duration, const CallSite& site,
                                core::TimePoint now) {
    Test* test = running_test();
    if (!test) {
        if (outside_tests_) {
            report_misuse(site.place, "ADVANCE_TIME outside a test: call TEST('name') before it");
        }
        return false;
    }
    const auto [wait, first] = test->waits.try_emplace(site.key, now);
    return now - wait->second >= duration;
}

bool TestRecorder::first_call(const CallSite& site) {
    Test* test = running_test();
    if (!test || std::ranges::find(test->called_sites, site.key) != test->called_sites.end()) {
        return false;
    }
    test->called_sites.push_back(site.key);
    return true;
}

void TestRecorder::fail_running(const CallSite& site, std::string text) {
    if (Test* test = running_test()) {
        fail(*test, {site.place, std::move(text)});
    }
}

void TestRecorder::end_cycle(core::TimePoint now) {
    for (Test& test : tests_) {
        if (test.running && now - test.started >= settings_.timeout) {
            fail(test, {test.result.place,
                        fmt::format("did not finish within {} of machine time (TEST_FINISHED() "
                                    "ends a test)",
                                    time_literal(settings_.timeout))});
            end(test, now);
        }
    }
    current_.reset();
    outside_tests_ = true;
    ++cycle_;
}

void TestRecorder::stop(const Failure& failure, core::TimePoint now) {
    for (Test& test : tests_) {
        if (test.running) {
            fail(test, failure);
            end(test, now);
        }
    }
}

bool TestRecorder::done() const {
    return began_any_ && std::ranges::none_of(tests_, &Test::running);
}

std::vector<TestResult> TestRecorder::results() const {
    std::vector<TestResult> results;
    results.reserve(tests_.size());
    for (const Test& test : tests_) {
        results.push_back(test.result);
    }
    return results;
}

void TestRecorder::fail(Test& test, Failure failure) {
    test.result.outcome = Outcome::Failed;
    test.result.failures.push_back(std::move(failure));
}

void TestRecorder::end(Test& test, core::TimePoint now) {
    test.running = false;
    test.result.machine_time = now - test.started;
    test.result.wall_seconds = wall_now() - test.wall_started;
}

void TestRecorder::report_misuse(const SourcePlace& place, std::string text) {
    if (!misuse_) {
        misuse_ = Failure{place, std::move(text)};
    }
}

Totals totals(const std::vector<SuiteResult>& suites) {
    Totals sum;
    for (const SuiteResult& suite : suites) {
        if (suite.error) {
            ++sum.failed;
        }
        for (const TestResult& test : suite.tests) {
            switch (test.outcome) {
            case Outcome::Passed:
                ++sum.passed;
                break;
            case Outcome::Failed:
                ++sum.failed;
                break;
            case Outcome::Skipped:
                ++sum.skipped;
                break;
            }
        }
    }
    return sum;
}

} // namespace eposp::plctest
