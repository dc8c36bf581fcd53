// `eposp test` end to end, as a user runs it (issue 15, "the framework tests itself"): suites
// that pass and suites that fail, with the exact report lines, exit codes, the options and the
// mistakes a user makes (docs/testing-plc-code.md).
#include "../eposp_command.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <string_view>
#include <vector>

namespace eposp::device {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::MatchesRegex;
using ::testing::Not;

/// The reported lines of the output (stdout and stderr).
std::vector<std::string> lines_of(const test::CommandResult& result) {
    return result.lines();
}

std::string last_line(const test::CommandResult& result) {
    const auto lines = result.lines();
    return lines.empty() ? std::string() : lines.back();
}

/// The output without its wall-time figures, the only thing two runs may differ in.
std::string without_wall_times(const std::string& output) {
    // Without std::regex: g++ 12 warns falsely inside it at -O1 under the sanitizers.
    constexpr std::string_view kWall = " s wall time";
    std::string text = output;
    for (auto end = text.find(kWall); end != std::string::npos; end = text.find(kWall, end)) {
        auto begin = end;
        while (begin > 0 && (std::isdigit(static_cast<unsigned char>(text[begin - 1])) ||
                             text[begin - 1] == '.')) {
            --begin;
        }
        text.replace(begin, end + kWall.size() - begin, "WALL");
        end = begin + 4;
    }
    return text;
}

/// A function block suite with one test whose body is `calls`, one assertion a line; the
/// assertions start at line kFirstCall.
constexpr int kFirstCall = 13;
std::string assertions_suite(const std::string& suite, const std::vector<std::string>& calls) {
    std::string text = "FUNCTION_BLOCK " + suite +
                       "\n"
                       "VAR\n"
                       "    s : STRING := 'abc';\n"
                       "    w : WSTRING := \"ac\";\n"
                       "    d3a : ARRAY[1..3] OF DINT := [1, 2, 3];\n"
                       "    d3b : ARRAY[1..3] OF DINT := [1, 2, 4];\n"
                       "    d4 : ARRAY[1..4] OF DINT := [1, 2, 3, 4];\n"
                       "    r2a : ARRAY[0..1] OF REAL := [1.0, 2.0];\n"
                       "    r2b : ARRAY[0..1] OF REAL := [1.0, 2.5];\n"
                       "    l2 : ARRAY[0..1] OF LREAL := [1.0, 2.0];\n"
                       "END_VAR\n"
                       "    TEST('Assertions');\n";
    for (const std::string& call : calls) {
        text += "    " + call + ";\n";
    }
    return text + "    TEST_FINISHED();\nEND_FUNCTION_BLOCK\n";
}

struct FailingAssertion {
    std::string call;
    std::string report; ///< what follows `file:line: Suite.Test: `
};

// Every assertion kind once with values that differ, and what the report says about it.
const std::vector<FailingAssertion> kFailingAssertions = {
    {"AssertEquals(T#1s, DINT#1000, 'mixed types')",
     "expected T#1s (TIME), got 1000 (DINT): mixed types"},
    {"AssertEquals(INT#3, INT#4, 'any int')", "expected 3, got 4: any int"},
    {"AssertEquals(TRUE, FALSE, 'any bool')", "expected TRUE, got FALSE: any bool"},
    {"AssertEquals(s, 'abd', 'any string')", "expected 'abc', got 'abd': any string"},
    {"AssertEquals(REAL#1.5, REAL#2.5, 'any real')", "expected 1.5, got 2.5: any real"},
    {"AssertEquals(T#1s, T#2s, 'any time')", "expected T#1s, got T#2s: any time"},
    {"AssertEquals_BOOL(TRUE, FALSE, 'bool')", "expected TRUE, got FALSE: bool"},
    {"AssertEquals_BYTE(16#0F, 16#F0, 'byte')", "expected 16#0F, got 16#F0: byte"},
    {"AssertEquals_WORD(1, 2, 'word')", "expected 16#0001, got 16#0002: word"},
    {"AssertEquals_DWORD(1, 2, 'dword')", "expected 16#00000001, got 16#00000002: dword"},
    {"AssertEquals_LWORD(1, 2, 'lword')",
     "expected 16#0000000000000001, got 16#0000000000000002: lword"},
    {"AssertEquals_SINT(-1, 2, 'sint')", "expected -1, got 2: sint"},
    {"AssertEquals_INT(-300, 2, 'int')", "expected -300, got 2: int"},
    {"AssertEquals_DINT(6, 5, 'dint')", "expected 6, got 5: dint"},
    {"AssertEquals_LINT(-1, 2, 'lint')", "expected -1, got 2: lint"},
    {"AssertEquals_USINT(1, 2, 'usint')", "expected 1, got 2: usint"},
    {"AssertEquals_UINT(1, 2, 'uint')", "expected 1, got 2: uint"},
    {"AssertEquals_UDINT(1, 2, 'udint')", "expected 1, got 2: udint"},
    {"AssertEquals_ULINT(1, 2, 'ulint')", "expected 1, got 2: ulint"},
    {"AssertEquals_TIME(T#1s, T#1s500ms, 'time')", "expected T#1s, got T#1s500ms: time"},
    {"AssertEquals_LTIME(LTIME#1s, LTIME#2s, 'ltime')", "expected LTIME#1s, got LTIME#2s: ltime"},
    {"AssertEquals_DATE(D#2024-01-01, D#2024-01-02, 'date')",
     "expected D#2024-01-01, got D#2024-01-02: date"},
    {"AssertEquals_TIME_OF_DAY(TOD#12:00:00, TOD#12:00:01, 'tod')",
     "expected TOD#12:00:00, got TOD#12:00:01: tod"},
    {"AssertEquals_DATE_AND_TIME(DT#2024-01-01-12:00:00, DT#2024-01-01-12:00:01, 'dt')",
     "expected DT#2024-01-01-12:00:00, got DT#2024-01-01-12:00:01: dt"},
    {"AssertEquals_REAL(1.5, 1.6, 0.01, 'real')", "expected 1.5 within 0.01, got 1.6: real"},
    {"AssertEquals_LREAL(1.0, 1.25, 0.1, 'lreal')", "expected 1 within 0.1, got 1.25: lreal"},
    {"AssertEquals_STRING('abd', s, 'string')", "expected 'abd', got 'abc': string"},
    {"AssertEquals_WSTRING(\"ab\", w, 'wstring')", "expected \"ab\", got \"ac\": wstring"},
    {"AssertTrue(FALSE, 'true')", "expected TRUE, got FALSE: true"},
    {"AssertFalse(TRUE, 'false')", "expected FALSE, got TRUE: false"},
    {"AssertArrayEquals_DINT(d3a, d4, 'sizes')", "expected 3 elements, got 4: sizes"},
    {"AssertArrayEquals_DINT(d3a, d3b, 'dints')", "expected 3 at index 3, got 4: dints"},
    {"AssertArrayEquals_REAL(r2a, r2b, 0.1, 'reals')", "expected 2 at index 1, got 2.5: reals"},
    {"AssertEquals_DINT(1, 2, '')", "expected 1, got 2"},
};

// The same kinds with values that agree (REAL and LREAL within their delta).
const std::vector<std::string> kPassingAssertions = {
    "AssertEquals(T#1s, T#1000ms, 'any time')",
    "AssertEquals(INT#3, INT#3, 'any int')",
    "AssertEquals(s, 'abc', 'any string')",
    "AssertEquals(REAL#1.5, REAL#1.5, 'any real')",
    "AssertEquals_BOOL(TRUE, TRUE, 'bool')",
    "AssertEquals_BYTE(16#0F, 15, 'byte')",
    "AssertEquals_WORD(1, 1, 'word')",
    "AssertEquals_DWORD(1, 1, 'dword')",
    "AssertEquals_LWORD(1, 1, 'lword')",
    "AssertEquals_SINT(-1, -1, 'sint')",
    "AssertEquals_INT(-300, -300, 'int')",
    "AssertEquals_DINT(5, 5, 'dint')",
    "AssertEquals_LINT(-1, -1, 'lint')",
    "AssertEquals_USINT(1, 1, 'usint')",
    "AssertEquals_UINT(1, 1, 'uint')",
    "AssertEquals_UDINT(1, 1, 'udint')",
    "AssertEquals_ULINT(1, 1, 'ulint')",
    "AssertEquals_TIME(T#1s500ms, T#1500ms, 'time')",
    "AssertEquals_LTIME(LTIME#1s, LTIME#1s, 'ltime')",
    "AssertEquals_DATE(D#2024-01-01, D#2024-01-01, 'date')",
    "AssertEquals_TIME_OF_DAY(TOD#12:00:00, TOD#12:00:00, 'tod')",
    "AssertEquals_DATE_AND_TIME(DT#2024-01-01-12:00:00, DT#2024-01-01-12:00:00, 'dt')",
    "AssertEquals_REAL(1.5, 1.505, 0.01, 'real')",
    "AssertEquals_LREAL(1.0, 1.05, 0.1, 'lreal')",
    "AssertEquals_STRING('abc', s, 'string')",
    "AssertEquals_WSTRING(\"ac\", w, 'wstring')",
    "AssertTrue(TRUE, 'true')",
    "AssertFalse(FALSE, 'false')",
    "AssertArrayEquals_DINT(d3a, d3a, 'dints')",
    "AssertArrayEquals_REAL(r2a, r2b, 0.5, 'reals')",
    "AssertArrayEquals_LREAL(l2, l2, 0.0, 'lreals')",
};

TEST(EpospTestCommand, SuiteWhoseAssertionsAllHoldPassesAndExitsZero) {
    const auto suite =
        write_source("passing_test.st", assertions_suite("Holds", kPassingAssertions));
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Holds: 1 passed, 0 failed (")) << result.output;
    EXPECT_EQ(last_line(result), "1 passed, 0 failed") << result.output;
}

TEST(EpospTestCommand, EachFailedAssertionIsReportedAtItsFileAndLine) {
    std::vector<std::string> calls;
    for (const FailingAssertion& assertion : kFailingAssertions) {
        calls.push_back(assertion.call);
    }
    const auto suite = write_source("failing_test.st", assertions_suite("Fails", calls));
    const auto result = eposp("test " + suite);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_EQ(last_line(result), "0 passed, 1 failed") << result.output;
    for (std::size_t i = 0; i < kFailingAssertions.size(); ++i) {
        const std::string line = fmt::format("{}:{}: Fails.Assertions: {}", suite, kFirstCall + i,
                                             kFailingAssertions[i].report);
        EXPECT_THAT(lines_of(result), Contains(line)) << result.output;
    }
}

// A counter counted once a cycle, the program under test of the cycle and time tests.
constexpr std::string_view kCounter = "FUNCTION_BLOCK Counter\n"
                                      "VAR_INPUT enable : BOOL; END_VAR\n"
                                      "VAR_OUTPUT count : DINT; END_VAR\n"
                                      "    IF enable THEN count := count + 1; END_IF\n"
                                      "END_FUNCTION_BLOCK\n";

TEST(EpospTestCommand, TestRunsCycleAfterCycleUntilItFinishes) {
    const auto program = write_source("counter.st", std::string(kCounter));
    const auto suite =
        write_source("counter_test.st", "FUNCTION_BLOCK Cycles\n"
                                        "VAR counter : Counter; END_VAR\n"
                                        "    TEST('CountsForTenCycles');\n"
                                        "    counter(enable := TRUE);\n"
                                        "    IF ADVANCE_TIME(T#10ms) THEN\n"
                                        "        AssertEquals_DINT(11, counter.count, 'cycles');\n"
                                        "        TEST_FINISHED();\n"
                                        "    END_IF\n"
                                        "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + program + " " + suite);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Cycles: 1 passed, 0 failed (0.011 s machine time"));
}

TEST(EpospTestCommand, TestThatNeverFinishesFailsAfterTheTimeout) {
    const auto suite = write_source("endless_test.st", "FUNCTION_BLOCK Endless\n"
                                                       "    TEST('Ends');\n"
                                                       "    TEST_FINISHED();\n"
                                                       "    TEST('NeverEnds');\n"
                                                       "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite + " --timeout 2s");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(lines_of(result),
                Contains(suite + ":4: Endless.NeverEnds: did not finish within T#2s of machine "
                                 "time (TEST_FINISHED() ends a test)"))
        << result.output;
    EXPECT_EQ(last_line(result), "1 passed, 1 failed");
}

TEST(EpospTestCommand, DisabledTestIsSkippedAndCounted) {
    const auto suite = write_source("disabled_test.st", "FUNCTION_BLOCK Later\n"
                                                        "    TEST('Works');\n"
                                                        "    TEST_FINISHED();\n"
                                                        "    TEST('disabled_NotYet');\n"
                                                        "    AssertTrue(FALSE, 'never run');\n"
                                                        "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, Not(HasSubstr("never run")));
    EXPECT_EQ(last_line(result), "1 passed, 0 failed, 1 skipped");
}

TEST(EpospTestCommand, WaitUntilWhoseConditionNeverHoldsFailsTheTest) {
    const auto suite = write_source("wait_test.st", "FUNCTION_BLOCK Waits\n"
                                                    "    TEST('ForNothing');\n"
                                                    "    IF WAIT_UNTIL(FALSE, T#50ms) THEN\n"
                                                    "        TEST_FINISHED();\n"
                                                    "    END_IF\n"
                                                    "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(lines_of(result), Contains(suite + ":3: Waits.ForNothing: WAIT_UNTIL timed out: "
                                                   "the condition did not hold within T#50ms"))
        << result.output;
    EXPECT_EQ(last_line(result), "0 passed, 1 failed");
}

TEST(EpospTestCommand, RunTimeErrorFailsTheTestAtItsLine) {
    const auto suite = write_source("divide_test.st", "FUNCTION_BLOCK Divides\n"
                                                      "VAR x : DINT; zero : DINT; END_VAR\n"
                                                      "    TEST('ByZero');\n"
                                                      "    x := 10 / zero;\n"
                                                      "    TEST_FINISHED();\n"
                                                      "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(lines_of(result), Contains(suite + ":4: Divides.ByZero: run-time error: division "
                                                   "by zero in Divides at line 4"))
        << result.output;
    EXPECT_EQ(last_line(result), "0 passed, 1 failed");
}

TEST(EpospTestCommand, EndlessLoopFailsTheTestInsteadOfHanging) {
    const auto suite = write_source("loop_test.st", "FUNCTION_BLOCK Loops\n"
                                                    "VAR i : DINT; END_VAR\n"
                                                    "    TEST('Forever');\n"
                                                    "    WHILE TRUE DO i := i + 1; END_WHILE\n"
                                                    "    TEST_FINISHED();\n"
                                                    "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(lines_of(result),
                Contains(suite + ":4: Loops.Forever: run-time error: "
                                 "instruction budget exceeded in Loops at line 4"))
        << result.output;
}

TEST(EpospTestCommand, AssertionThatFailsInEveryCycleIsReportedOnce) {
    const auto suite = write_source("repeat_test.st", "FUNCTION_BLOCK Repeats\n"
                                                      "    TEST('TenCycles');\n"
                                                      "    AssertTrue(FALSE, 'each cycle');\n"
                                                      "    IF ADVANCE_TIME(T#10ms) THEN\n"
                                                      "        TEST_FINISHED();\n"
                                                      "    END_IF\n"
                                                      "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    const auto lines = lines_of(result);
    EXPECT_EQ(std::ranges::count(lines, suite + ":3: Repeats.TenCycles: expected TRUE, got FALSE: "
                                                "each cycle"),
              1)
        << result.output;
    EXPECT_EQ(last_line(result), "0 passed, 1 failed");
}

TEST(EpospTestCommand, AssertionOutsideATestFailsTheSuite) {
    const auto suite = write_source("outside_test.st", "FUNCTION_BLOCK Outside\n"
                                                       "    AssertTrue(FALSE, 'where?');\n"
                                                       "    TEST('Fine');\n"
                                                       "    TEST_FINISHED();\n"
                                                       "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(lines_of(result), Contains(suite + ":2: Outside: an assertion outside a test: "
                                                   "call TEST('name') before it"))
        << result.output;
    EXPECT_EQ(last_line(result), "1 passed, 1 failed");
}

TEST(EpospTestCommand, SameTestNameTwiceFailsTheSuite) {
    const auto suite = write_source("twice_test.st", "FUNCTION_BLOCK Twice\n"
                                                     "    TEST('Same');\n"
                                                     "    TEST_FINISHED();\n"
                                                     "    TEST('Same');\n"
                                                     "    TEST_FINISHED();\n"
                                                     "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(lines_of(result),
                Contains(suite + ":4: Twice: TEST('Same') is called twice in one cycle: the tests "
                                 "of a suite need names of their own"))
        << result.output;
    EXPECT_EQ(last_line(result), "1 passed, 1 failed");
}

TEST(EpospTestCommand, ProgramAndFunctionBlockSuitesInSeveralFilesRunTheProgramUnderTest) {
    // The program's CONFIGURATION names a task and an instance; the harness brings its own.
    const auto program =
        write_source("machine.st", std::string(kCounter) +
                                       "PROGRAM Main\n"
                                       "VAR c : Counter; END_VAR\n"
                                       "    c(enable := TRUE);\n"
                                       "END_PROGRAM\n"
                                       "CONFIGURATION Cell\n"
                                       "    RESOURCE EposP ON EPOS_P\n"
                                       "        TASK Fast (INTERVAL := T#10ms, PRIORITY := 1);\n"
                                       "        PROGRAM Run WITH Fast : Main;\n"
                                       "    END_RESOURCE\n"
                                       "END_CONFIGURATION\n");
    const auto program_suite =
        write_source("program_test.st", "PROGRAM ProgramSuite\n"
                                        "VAR c : Counter; END_VAR\n"
                                        "    TEST('CountsOnce');\n"
                                        "    c(enable := TRUE);\n"
                                        "    AssertEquals_DINT(1, c.count, 'first cycle');\n"
                                        "    TEST_FINISHED();\n"
                                        "END_PROGRAM\n");
    const auto block_suites =
        write_source("block_test.st", "FUNCTION_BLOCK BlockSuite\n"
                                      "VAR c : Counter; END_VAR\n"
                                      "    TEST('Idle');\n"
                                      "    c(enable := FALSE);\n"
                                      "    AssertEquals_DINT(0, c.count, 'idle');\n"
                                      "    TEST_FINISHED();\n"
                                      "END_FUNCTION_BLOCK\n"
                                      "FUNCTION_BLOCK OtherSuite\n"
                                      "    TEST('Trivial');\n"
                                      "    TEST_FINISHED();\n"
                                      "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + program + " " + program_suite + " " + block_suites);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("ProgramSuite: 1 passed, 0 failed ("));
    EXPECT_THAT(result.output, HasSubstr("BlockSuite: 1 passed, 0 failed ("));
    EXPECT_THAT(result.output, HasSubstr("OtherSuite: 1 passed, 0 failed ("));
    EXPECT_EQ(last_line(result), "3 passed, 0 failed");
}

TEST(EpospTestCommand, GlobalsOfTheIgnoredConfigurationStay) {
    const auto program = write_source("globals.st", "FUNCTION_BLOCK UsesGlobal\n"
                                                    "VAR_EXTERNAL MaxSpeed : DINT; END_VAR\n"
                                                    "VAR_OUTPUT v : DINT; END_VAR\n"
                                                    "    v := MaxSpeed;\n"
                                                    "END_FUNCTION_BLOCK\n"
                                                    "CONFIGURATION Cell\n"
                                                    "    VAR_GLOBAL MaxSpeed : DINT := 7; END_VAR\n"
                                                    "    RESOURCE EposP ON EPOS_P\n"
                                                    "    END_RESOURCE\n"
                                                    "END_CONFIGURATION\n");
    const auto suite = write_source("globals_test.st", "FUNCTION_BLOCK Globals\n"
                                                       "VAR u : UsesGlobal; END_VAR\n"
                                                       "    TEST('ReadsTheGlobal');\n"
                                                       "    u();\n"
                                                       "    AssertEquals_DINT(7, u.v, 'global');\n"
                                                       "    TEST_FINISHED();\n"
                                                       "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + program + " " + suite);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(last_line(result), "1 passed, 0 failed");
}

/// A suite that powers axis `axis`, moves it to 10000 qc and asserts where it stands and its
/// PLCopen state.
std::string motion_suite(int axis) {
    return fmt::format(
        "FUNCTION_BLOCK MotionSuite\n"
        "VAR\n"
        "    Axis : AXIS_REF := (AxisNo := {});\n"
        "    Power : MC_Power;\n"
        "    Move : MC_MoveAbsolute;\n"
        "    Position : MC_ReadActualPosition;\n"
        "    State : MC_ReadStatus;\n"
        "END_VAR\n"
        "    Power(Axis := Axis, Enable := TRUE);\n"
        "    Position(Axis := Axis, Enable := TRUE);\n"
        "    State(Axis := Axis, Enable := TRUE);\n"
        "    TEST('MovesToTarget');\n"
        "    IF WAIT_UNTIL(Power.Status, T#2s) THEN\n"
        "        Move(Axis := Axis, Execute := TRUE, Position := 10000, "
        "Velocity := 2500, Acceleration := 10000, Deceleration := 10000);\n"
        "        IF WAIT_UNTIL(Move.Done, T#5s) THEN\n"
        "            AssertEquals_LREAL(10000.0, Position.Position, 50.0, 'where');\n"
        "            AssertTrue(State.Standstill, 'standing still');\n"
        "            AssertFalse(State.ErrorStop, 'no error');\n"
        "            AssertEquals_LREAL(0.0, Position.Position, 50.0, 'fails');\n"
        "            TEST_FINISHED();\n"
        "        END_IF\n"
        "    END_IF\n"
        "END_FUNCTION_BLOCK\n",
        axis);
}

// Line 19 of motion_suite asserts the axis still at 0 after the move: it must fail with the
// position reached, which shows the test read the drive's real position.
void expect_moved_to_target(const test::CommandResult& result, const std::string& suite) {
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(result.output, Not(HasSubstr("where"))) << result.output;
    EXPECT_THAT(result.output, Not(HasSubstr("standing still")));
    EXPECT_THAT(result.output, Not(HasSubstr("no error")));
    EXPECT_THAT(
        result.output,
        HasSubstr(suite + ":19: MotionSuite.MovesToTarget: expected 0 within 50, got 9997: fails"))
        << result.output;
    EXPECT_EQ(last_line(result), "0 passed, 1 failed");
}

TEST(EpospTestCommand, TestMovesTheInternalAxisOfTheDefaultDevice) {
    const auto suite = write_source("motion_test.st", motion_suite(0));
    expect_moved_to_target(eposp("test " + suite), suite);
}

TEST(EpospTestCommand, TestMovesAnEpos2OnPort2OfANetworkFile) {
    const auto network = write_source("network.yaml", "sync_period: 1ms\n"
                                                      "slaves:\n"
                                                      "  - node: 1\n"
                                                      "    port: internal\n"
                                                      "    axis: 0\n"
                                                      "  - node: 2\n"
                                                      "    port: can\n"
                                                      "    axis: 1\n");
    const auto suite = write_source("motion_test.st", motion_suite(1));
    expect_moved_to_target(eposp("test " + suite + " --network " + network), suite);
}

TEST(EpospTestCommand, MockReplacesABlockForItsSuiteOnly) {
    const auto program = write_source("sensor.st", "FUNCTION_BLOCK FB_Sensor\n"
                                                   "VAR_OUTPUT value : DINT; END_VAR\n"
                                                   "    value := 1;\n"
                                                   "END_FUNCTION_BLOCK\n"
                                                   "FUNCTION_BLOCK FB_Reader\n"
                                                   "VAR sensor : FB_Sensor; END_VAR\n"
                                                   "VAR_OUTPUT value : DINT; END_VAR\n"
                                                   "    sensor();\n"
                                                   "    value := sensor.value;\n"
                                                   "END_FUNCTION_BLOCK\n");
    const auto suites =
        write_source("reader_test.st", "FUNCTION_BLOCK FB_FakeSensor\n"
                                       "VAR_OUTPUT value : DINT; END_VAR\n"
                                       "    value := 42;\n"
                                       "END_FUNCTION_BLOCK\n"
                                       "\n"
                                       "// reads the double\n"
                                       "{attribute 'mock' := 'FB_Sensor => FB_FakeSensor'}\n"
                                       "FUNCTION_BLOCK MockedSuite\n"
                                       "VAR reader : FB_Reader; END_VAR\n"
                                       "    TEST('ReadsTheDouble');\n"
                                       "    reader();\n"
                                       "    AssertEquals_DINT(42, reader.value, 'double');\n"
                                       "    TEST_FINISHED();\n"
                                       "END_FUNCTION_BLOCK\n"
                                       "\n"
                                       "FUNCTION_BLOCK RealSuite\n"
                                       "VAR reader : FB_Reader; END_VAR\n"
                                       "    TEST('ReadsTheSensor');\n"
                                       "    reader();\n"
                                       "    AssertEquals_DINT(1, reader.value, 'original');\n"
                                       "    TEST_FINISHED();\n"
                                       "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + program + " " + suites);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(last_line(result), "2 passed, 0 failed");
}

// Two suites, three tests: A.One, A.Two, B.One.
std::string two_suites() {
    return write_source("filter_test.st", "FUNCTION_BLOCK A\n"
                                          "    TEST('One');\n"
                                          "    TEST_FINISHED();\n"
                                          "    TEST('Two');\n"
                                          "    AssertTrue(FALSE, 'A.Two ran');\n"
                                          "    TEST_FINISHED();\n"
                                          "END_FUNCTION_BLOCK\n"
                                          "FUNCTION_BLOCK B\n"
                                          "    TEST('One');\n"
                                          "    AssertTrue(FALSE, 'B.One ran');\n"
                                          "    TEST_FINISHED();\n"
                                          "END_FUNCTION_BLOCK\n");
}

TEST(EpospTestCommand, FilterRunsOnlyTheTestsItsGlobsSelect) {
    const auto suites = two_suites();
    const auto only_a = eposp("test " + suites + " --filter 'A.*'");
    EXPECT_EQ(last_line(only_a), "1 passed, 1 failed") << only_a.output;
    EXPECT_THAT(only_a.output, Not(HasSubstr("B.One ran")));
    EXPECT_THAT(only_a.output, Not(HasSubstr("B:")));

    const auto ones = eposp("test " + suites + " --filter '*.One'");
    EXPECT_EQ(last_line(ones), "1 passed, 1 failed") << ones.output;
    EXPECT_THAT(ones.output, HasSubstr("B.One ran"));
    EXPECT_THAT(ones.output, Not(HasSubstr("A.Two ran")));

    const auto passing = eposp("test " + suites + " --filter 'A.One'");
    EXPECT_EQ(passing.exit_code, 0) << passing.output;
    EXPECT_EQ(last_line(passing), "1 passed, 0 failed");
}

TEST(EpospTestCommand, FilterLeavesOutTheTestsAfterAMinus) {
    const auto suites = two_suites();
    const auto without_b = eposp("test " + suites + " --filter '-B.*'");
    EXPECT_EQ(last_line(without_b), "1 passed, 1 failed") << without_b.output;
    EXPECT_THAT(without_b.output, Not(HasSubstr("B.One ran")));

    const auto only_passing = eposp("test " + suites + " --filter 'A.*:B.*-*.Two:B.One'");
    EXPECT_EQ(only_passing.exit_code, 0) << only_passing.output;
    EXPECT_EQ(last_line(only_passing), "1 passed, 0 failed");
}

// Suites of every outcome: passed, failed, skipped, timed out, and a suite that fails as a whole
// (an assertion outside its tests). Their names and messages hold XML's special characters.
std::vector<std::string> suites_of_every_outcome() {
    return {write_source("outcomes_test.st", "FUNCTION_BLOCK Outcomes\n"
                                             "    TEST('Passes');\n"
                                             "    TEST_FINISHED();\n"
                                             "    TEST('Fails');\n"
                                             "    AssertEquals_STRING('<a & \"b\">', 'c', '<&>');\n"
                                             "    AssertTrue(FALSE, 'twice');\n"
                                             "    TEST_FINISHED();\n"
                                             "    TEST('disabled_Skipped');\n"
                                             "    TEST('TimesOut');\n"
                                             "END_FUNCTION_BLOCK\n"),
            write_source("broken_test.st", "PROGRAM Broken\n"
                                           "    AssertTrue(FALSE, 'outside');\n"
                                           "    TEST('Fine');\n"
                                           "    TEST_FINISHED();\n"
                                           "END_PROGRAM\n")};
}

std::string joined(const std::vector<std::string>& paths) {
    std::string text;
    for (const std::string& path : paths) {
        text += " " + path;
    }
    return text;
}

TEST(EpospTestJunit, ReportMatchesTheJunitSchemaOfJenkinsAndGitlab) {
    if (test::run_command("command -v xmllint >/dev/null").exit_code != 0) {
        GTEST_SKIP() << "xmllint (libxml2-utils) is not installed";
    }
    const auto report = scratch("report.xml");
    const auto result = eposp("test" + joined(suites_of_every_outcome()) +
                              " --timeout 1s --junit " + report.string());
    EXPECT_EQ(last_line(result), "2 passed, 3 failed, 1 skipped") << result.output;
    const std::filesystem::path schema = EPOSP_JUNIT_SCHEMA;
    const auto valid = test::run_command("xmllint --noout --schema " + schema.string() + " " +
                                         report.string() + " 2>&1");
    EXPECT_EQ(valid.exit_code, 0) << valid.output << read_file(report);
    const std::string xml = read_file(report);
    EXPECT_THAT(xml, HasSubstr("<skipped"));
    EXPECT_THAT(xml, HasSubstr("<error"));
    EXPECT_THAT(xml, HasSubstr("<failure message=\"expected &apos;&lt;a &amp; &quot;b&quot;&gt;"
                               "&apos;, got &apos;c&apos;: &lt;&amp;&gt;\""));
}

TEST(EpospTestJunit, ReportRefusesToOverwriteAnInputFile) {
    const auto suite = write_source("input_test.st", "FUNCTION_BLOCK Input\n"
                                                     "    TEST('T');\n"
                                                     "    TEST_FINISHED();\n"
                                                     "END_FUNCTION_BLOCK\n");
    const std::string before = read_file(suite);
    const auto result = eposp("test " + suite + " --junit " + suite);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("--junit " + suite + " would overwrite the input"));
    EXPECT_EQ(read_file(suite), before);
}

TEST(EpospTestDeterminism, TwoRunsReportTheSameButForWallTimes) {
    const auto files = joined(suites_of_every_outcome()) + " " + two_suites();
    const auto first = eposp("test" + files + " --timeout 1s");
    const auto second = eposp("test" + files + " --timeout 1s");
    EXPECT_EQ(without_wall_times(first.output), without_wall_times(second.output));
    EXPECT_EQ(first.exit_code, second.exit_code);
}

TEST(EpospTestDeterminism, OneJobAndFourJobsReportTheSameButForWallTimes) {
    const auto files = joined(suites_of_every_outcome()) + " " + two_suites();
    const auto one = eposp("test" + files + " --timeout 1s --jobs 1");
    const auto four = eposp("test" + files + " --timeout 1s --jobs 4 --seed 7");
    EXPECT_EQ(without_wall_times(one.output), without_wall_times(four.output));
    EXPECT_THAT(one.output, HasSubstr("Outcomes: "));
    EXPECT_THAT(one.output, HasSubstr("Broken: "));
}

// The program under test in one file, its suite in another.
std::vector<std::string> counter_and_suite() {
    return {write_source("counter.st", std::string(kCounter)),
            write_source("counter_test.st", "FUNCTION_BLOCK Counts\n"
                                            "VAR c : Counter; END_VAR\n"
                                            "    TEST('Once');\n"
                                            "    c(enable := TRUE);\n"
                                            "    AssertEquals_DINT(1, c.count, 'once');\n"
                                            "    TEST_FINISHED();\n"
                                            "END_FUNCTION_BLOCK\n")};
}

TEST(EpospTestCoverage, LcovTracefileNamesTheUserFiles) {
    const auto files = counter_and_suite();
    const auto tracefile = scratch("coverage.info");
    const auto result = eposp("test" + joined(files) + " --lcov " + tracefile.string());
    EXPECT_EQ(result.exit_code, 0) << result.output;
    const std::string lcov = read_file(tracefile);
    EXPECT_THAT(lcov, HasSubstr("SF:" + files[0] + "\n"));
    EXPECT_THAT(lcov, HasSubstr("SF:" + files[1] + "\n"));
    EXPECT_THAT(lcov, Not(HasSubstr("SF:<")));
}

TEST(EpospTestCoverage, CoveragePrintsASummaryPerPou) {
    const auto result = eposp("test" + joined(counter_and_suite()) + " --coverage");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("\ncoverage:\n"));
    // Counter's IF is not counted as a branch yet (reported to the coverage area): only the
    // form of its line is checked.
    EXPECT_THAT(lines_of(result),
                Contains(MatchesRegex(
                    R"(Counter: lines [0-9]+/[0-9]+ \([0-9.]+%\), branches [0-9]+/[0-9]+)")))
        << result.output;
    EXPECT_THAT(lines_of(result), Contains("Counts: lines 4/4 (100.0%), branches 0/0"));
    EXPECT_THAT(result.output, Not(HasSubstr("EPOSP_TEST"))); // the harness is not the user's
}

TEST(EpospTestBadInput, FilterThatSelectsNoTestFails) {
    const auto result = eposp("test " + two_suites() + " --filter 'C.*'");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp test: error: --filter 'C.*' selects no test"));
}

TEST(EpospTestBadInput, NoFilesIsRefused) {
    const auto result = eposp("test");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("files is required"));
}

TEST(EpospTestBadInput, MissingFileIsNamed) {
    const auto missing = scratch("missing.st").string();
    const auto result = eposp("test " + missing);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("cannot open '" + missing + "'"));
}

TEST(EpospTestBadInput, DirectoryIsNotAnStFile) {
    const auto directory = scratch("sources");
    std::filesystem::create_directory(directory);
    const auto result = eposp("test " + directory.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(directory.string() + " is a directory, not an ST file"));
}

TEST(EpospTestBadInput, FileGivenTwiceIsRefused) {
    const auto suite = two_suites();
    const auto other_name = (scratch(".") / "filter_test.st").string();
    const auto result = eposp("test " + suite + " " + other_name);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp test: error: " + other_name +
                                         " is given twice (also as " + suite + ")"));
}

TEST(EpospTestBadInput, FilesWithoutASuiteSayWhatASuiteIs) {
    const auto result = eposp("test " + write_source("counter.st", std::string(kCounter)));
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output,
                HasSubstr("eposp test: error: no test suite in the files: a suite is a "
                          "FUNCTION_BLOCK or PROGRAM whose body calls TEST('name')"));
}

TEST(EpospTestBadInput, FileThatDoesNotParseGivesTheCompilersMessage) {
    const auto suite = write_source("broken_test.st", "FUNCTION_BLOCK Broken\n"
                                                      "    TEST('T');\n"
                                                      "    x := ;\n"
                                                      "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(suite + ":3:10: error: expected an expression"));
}

TEST(EpospTestBadInput, SuiteThatDoesNotCompileFailsWithTheCompilersMessage) {
    const auto suite = write_source("undeclared_test.st", "FUNCTION_BLOCK Undeclared\n"
                                                          "    TEST('T');\n"
                                                          "    AssertEquals_DINT(1, nowhere, '');\n"
                                                          "    TEST_FINISHED();\n"
                                                          "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(suite + ":1: Undeclared: does not compile:"));
    EXPECT_THAT(result.output, HasSubstr(suite + ":3:26: error: undeclared identifier 'nowhere'"));
    EXPECT_EQ(last_line(result), "0 passed, 1 failed");
}

TEST(EpospTestBadInput, ErrorFormatJsonPrintsEachDiagnosticOnceAsJson) {
    // Two suites: each compiles the same files, so each error would be found twice.
    const auto suite = write_source("two_suites_test.st", "FUNCTION_BLOCK First\n"
                                                          "    TEST('T');\n"
                                                          "    AssertEquals_DINT(1, nowhere, '');\n"
                                                          "    TEST_FINISHED();\n"
                                                          "END_FUNCTION_BLOCK\n"
                                                          "FUNCTION_BLOCK Second\n"
                                                          "    TEST('T');\n"
                                                          "    TEST_FINISHED();\n"
                                                          "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test --error-format json " + suite);
    EXPECT_EQ(result.exit_code, 1);
    const std::string json =
        "{\"code\":\"E0201\",\"severity\":\"error\",\"title\":\"undeclared "
        "identifier\",\"message\":\"undeclared identifier 'nowhere'\",\"file\":\"" +
        suite + "\",\"range\":{\"start\":{\"line\":3,\"column\":26}";
    EXPECT_EQ(
        std::ranges::count_if(lines_of(result),
                              [&json](const std::string& line) { return line.starts_with(json); }),
        1)
        << result.output;
    // The report still says which suite could not run.
    EXPECT_THAT(result.output, HasSubstr(suite + ":1: First: does not compile:"));
}

TEST(EpospTestBadInput, ErrorFormatJsonShowsParseErrorsAsJson) {
    const auto suite = write_source("broken_test.st", "FUNCTION_BLOCK Broken\n"
                                                      "    TEST('T');\n"
                                                      "    x := ;\n"
                                                      "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test --error-format json " + suite);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("\"severity\":\"error\""));
    EXPECT_THAT(result.output,
                HasSubstr("\"file\":\"" + suite + "\",\"range\":{\"start\":{\"line\":3,"));
}

TEST(EpospTestBadInput, MalformedMockAttributeIsShownAtItsLine) {
    const auto suite =
        write_source("mock_test.st", "FUNCTION_BLOCK FB_Double\n"
                                     "END_FUNCTION_BLOCK\n"
                                     "{attribute 'mock' := 'FB_Original -> FB_Double'}\n"
                                     "FUNCTION_BLOCK Mocked\n"
                                     "    TEST('T');\n"
                                     "    TEST_FINISHED();\n"
                                     "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, Not(HasSubstr("error: " + suite))); // one "error:", the file's
    EXPECT_THAT(result.output, HasSubstr(suite + ":3: error: a mock attribute reads {attribute "
                                                 "'mock' := 'FB_Name => FB_Double'}"));
}

TEST(EpospTestBadInput, MockOfAnUnknownBlockFailsItsSuite) {
    const auto suite =
        write_source("unknown_mock_test.st", "FUNCTION_BLOCK FB_Double\n"
                                             "END_FUNCTION_BLOCK\n"
                                             "{attribute 'mock' := 'FB_Nowhere => FB_Double'}\n"
                                             "FUNCTION_BLOCK Mocked\n"
                                             "    TEST('T');\n"
                                             "    TEST_FINISHED();\n"
                                             "END_FUNCTION_BLOCK\n");
    const auto result = eposp("test " + suite);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr(suite + ":4: Mocked: does not compile:"));
    EXPECT_THAT(result.output, HasSubstr("no FUNCTION_BLOCK named 'FB_Nowhere'"));
    EXPECT_EQ(last_line(result), "0 passed, 1 failed");
}

TEST(EpospTestBadInput, BadTimeoutIsNamedInTheMessage) {
    const auto result = eposp("test " + two_suites() + " --timeout soon");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("--timeout: 'soon' is not a duration"));
}

TEST(EpospTestBadInput, ZeroTimeoutIsRefused) {
    const auto result = eposp("test " + two_suites() + " --timeout 0s");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp test: error: --timeout 0s: a test needs some "
                                         "machine time to run"));
    EXPECT_THAT(result.output, Not(HasSubstr("passed")));
}

} // namespace
} // namespace eposp::device
