// Coverage recorded by the interpreter (docs/runtime.md, "Coverage"): how often each line ran,
// each outcome of an IF, a loop and a CASE was taken, an inlined function's lines counted for
// that function, reports of several runs merged, and nothing counted when it is off.

#include "eposp/vm/coverage_report.hpp"
#include "eposp/vm/machine.hpp"
#include "runtime_harness.hpp"

#include <algorithm>

namespace eposp::vm::test {
namespace {

// Twice is a small leaf function: the compiler puts its body in place of the call. The IF's
// branches have two statements each, so it stays a branch (not a conditional move).
constexpr const char* kProgram = R"(FUNCTION Twice : DINT
  VAR_INPUT x : DINT; END_VAR
  Twice := x * 2;
END_FUNCTION
PROGRAM Main
  VAR n : DINT; i : DINT; odd : DINT; even : DINT; a : DINT; b : DINT; c : DINT; END_VAR
  n := n + 1;
  IF n MOD 2 = 1 THEN
    odd := odd + 1;
    a := Twice(n);
  ELSE
    even := even + 1;
    b := b + 1;
  END_IF;
  FOR i := 1 TO 3 DO
    c := c + 1;
  END_FOR;
  CASE n OF
    1: a := 10;
    2: b := 20;
    3: c := 30;
  ELSE
    c := 0;
  END_CASE;
END_PROGRAM
)";

/// The 1-based line of kProgram where `text` first appears.
std::uint32_t line_of(std::string_view text) {
    const std::string_view source = kProgram;
    const auto at = source.find(text);
    EXPECT_NE(at, std::string_view::npos) << text;
    return static_cast<std::uint32_t>(std::count(source.begin(), source.begin() + at, '\n') + 1);
}

/// The outcomes of the branch points on `line`, one vector each.
std::vector<std::vector<std::uint64_t>> branches_on(const PouCoverage& pou, std::uint32_t line) {
    std::vector<std::vector<std::uint64_t>> found;
    for (const auto& [point, taken] : pou.branches) {
        if (point.line == line) {
            found.push_back(taken);
        }
    }
    return found;
}

/// kProgram linked for `engine`, and a machine that ran `cycles` cycles of its task.
class CoverageRun {
public:
    CoverageRun(int cycles, Coverage coverage, Engine engine = Engine::Interpreter) {
        stdlib::register_standard_library(natives_);
        auto image = RuntimeHarness::compile_st(kProgram);
        EXPECT_TRUE(image);
        auto linked = link(std::move(*image), natives_, engine);
        EXPECT_TRUE(linked) << linked.error();
        program_.emplace(std::move(*linked));
        machine_.emplace(*program_, coverage);
        for (int cycle = 0; cycle < cycles; ++cycle) {
            EXPECT_EQ(machine_->run_cycle(0), RunState::Finished);
        }
    }
    CoverageReport report() const { return machine_->coverage(); }
    const Image& image() const { return program_->image(); }

private:
    NativeRegistry natives_;
    std::optional<Program> program_;
    std::optional<Machine> machine_;
};

TEST(Coverage, CountsHowOftenEachLineRan) {
    const CoverageRun run(5, Coverage::Record);
    const CoverageReport report = run.report();
    const PouCoverage& main = report.pous.at("Main");
    EXPECT_EQ(main.calls, 5u);
    EXPECT_EQ(main.lines.at(line_of("n := n + 1")), 5u);
    EXPECT_EQ(main.lines.at(line_of("odd := odd + 1")), 3u); // n = 1, 3, 5
    EXPECT_EQ(main.lines.at(line_of("even := even + 1")), 2u);
    EXPECT_EQ(main.lines.at(line_of("c := c + 1")), 15u);
    EXPECT_EQ(main.lines.at(line_of("1: a := 10")), 1u);
    EXPECT_EQ(main.lines.at(line_of("c := 0")), 2u); // n = 4, 5
    // Lines without code (END_IF, ELSE) are not lines of the report.
    EXPECT_FALSE(main.lines.contains(line_of("END_IF")));
}

TEST(Coverage, CountsBothOutcomesOfAnIfAndALoop) {
    const CoverageRun run(5, Coverage::Record);
    const CoverageReport report = run.report();
    const PouCoverage& main = report.pous.at("Main");
    auto if_branches = branches_on(main, line_of("IF n MOD 2"));
    ASSERT_EQ(if_branches.size(), 1u);
    std::sort(if_branches[0].begin(), if_branches[0].end());
    EXPECT_EQ(if_branches[0], (std::vector<std::uint64_t>{2, 3}));
    // The loop's back-edge: twice round, once out, in each of the 5 cycles.
    bool back_edge = false;
    for (auto line = line_of("FOR i := 1"); line <= line_of("END_FOR"); ++line) {
        for (const auto& taken : branches_on(main, line)) {
            back_edge = back_edge || taken == std::vector<std::uint64_t>{10, 5};
        }
    }
    EXPECT_TRUE(back_edge);
}

TEST(Coverage, CountsEachEntryOfACaseJumpTable) {
    const CoverageRun run(5, Coverage::Record);
    const CoverageReport report = run.report();
    const PouCoverage& main = report.pous.at("Main");
    const auto case_branches = branches_on(main, line_of("CASE n OF"));
    ASSERT_EQ(case_branches.size(), 1u);
    // Labels 1, 2, 3 once each, then twice past the table's end (ELSE).
    EXPECT_EQ(case_branches[0], (std::vector<std::uint64_t>{1, 1, 1, 2}));
}

TEST(Coverage, CountsAnInlinedFunctionsLinesForTheFunction) {
    const CoverageRun run(5, Coverage::Record);
    const auto main_index = std::find_if(run.image().pous.begin(), run.image().pous.end(),
                                         [](const Pou& pou) { return pou.name == "Main"; });
    ASSERT_FALSE(main_index->inlined.empty()) << "Twice is no longer inlined: the test is moot";
    const CoverageReport report = run.report();
    const PouCoverage& twice = report.pous.at("Twice");
    EXPECT_EQ(twice.calls, 3u);
    EXPECT_EQ(twice.lines.at(line_of("Twice := x * 2")), 3u);
    EXPECT_FALSE(report.pous.at("Main").lines.contains(line_of("Twice := x * 2")));
    EXPECT_EQ(report.pous.at("Main").lines.at(line_of("a := Twice(n)")), 3u);
}

// A REPEAT at the very top of a body jumps back to its first instruction: those runs are not
// entries of the POU (nor of its inlined copies).
TEST(Coverage, CountsEntriesNotLoopRoundsAtTheTopOfABody) {
    NativeRegistry natives;
    stdlib::register_standard_library(natives);
    auto image = RuntimeHarness::compile_st(R"(FUNCTION_BLOCK Spin
  VAR_INPUT k : DINT; END_VAR
  REPEAT k := k + 1; UNTIL k >= 3 END_REPEAT;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR s : Spin; END_VAR
  s(k := 0);
  s(k := 1);
END_PROGRAM
)");
    ASSERT_TRUE(image);
    auto program = link(std::move(*image), natives, Engine::Interpreter);
    ASSERT_TRUE(program) << program.error();
    Machine machine(*program, Coverage::Record);
    EXPECT_EQ(machine.run_cycle(0), RunState::Finished);
    const CoverageReport report = machine.coverage();
    EXPECT_EQ(report.pous.at("Spin").calls, 2u);
    EXPECT_EQ(report.pous.at("Spin").lines.at(3), 3u + 2u); // rounds from k = 0, then 1
    EXPECT_EQ(report.pous.at("Main").lines.at(7), 1u);      // the call, its copy entered once
}

TEST(Coverage, RecordsOnTheInterpreterWhateverTheEngine) {
    const CoverageRun run(2, Coverage::Record, Engine::Compiled);
    EXPECT_EQ(run.report().pous.at("Main").lines.at(line_of("n := n + 1")), 2u);
}

TEST(Coverage, CountsNothingWhenOff) {
    EXPECT_TRUE(CoverageRun(3, Coverage::Off).report().pous.empty());
    EXPECT_TRUE(CoverageRun(3, Coverage::Off, Engine::Compiled).report().pous.empty());
}

TEST(Coverage, MergedReportsAddTheirCounts) {
    CoverageReport merged = CoverageRun(5, Coverage::Record).report();
    merged.merge(CoverageRun(2, Coverage::Record).report());
    const PouCoverage& main = merged.pous.at("Main");
    EXPECT_EQ(main.calls, 7u);
    EXPECT_EQ(main.lines.at(line_of("n := n + 1")), 7u);
    EXPECT_EQ(main.lines.at(line_of("odd := odd + 1")), 4u);
    EXPECT_EQ(branches_on(main, line_of("CASE n OF"))[0], (std::vector<std::uint64_t>{2, 2, 1, 2}));

    CoverageReport other;
    other.pous["Other"].lines[3] = 1;
    other.pous["Main"].lines[999] = 4;
    other.pous["Main"].branches[BranchPoint{999, 0}] = {0, 4};
    merged.merge(other);
    EXPECT_EQ(merged.pous.at("Other").lines.at(3), 1u);
    EXPECT_EQ(merged.pous.at("Main").lines.at(999), 4u);
    EXPECT_EQ(merged.pous.at("Main").branches.at(BranchPoint{999, 0}),
              (std::vector<std::uint64_t>{0, 4}));
}

TEST(Coverage, RuntimeRecordsWhenConfiguredTo) {
    RuntimeConfig config;
    config.coverage = Coverage::Record;
    RuntimeHarness h(config);
    EXPECT_TRUE(h.runtime->coverage().pous.empty()); // nothing loaded
    ASSERT_EQ(h.load(kProgram), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.run_until(std::chrono::milliseconds(25)); // cycles at 0, 10 and 20 ms
    EXPECT_EQ(h.runtime->coverage().pous.at("Main").lines.at(line_of("n := n + 1")), 3u);

    RuntimeHarness off;
    ASSERT_EQ(off.load(kProgram), "");
    ASSERT_FALSE(off.runtime->start(StartMode::Cold));
    off.run_until(std::chrono::milliseconds(25));
    EXPECT_TRUE(off.runtime->coverage().pous.empty());
}

TEST(Coverage, SummaryGivesLinesAndBranchOutcomesPerPou) {
    CoverageReport report;
    PouCoverage& main = report.pous["Main"];
    for (std::uint32_t line = 1; line <= 14; ++line) {
        main.lines[line] = line <= 12 ? 1 : 0;
    }
    main.branches[BranchPoint{2, 0}] = {1, 1};
    main.branches[BranchPoint{3, 0}] = {1, 0};
    main.branches[BranchPoint{4, 0}] = {2, 1, 0, 0};
    report.pous["Empty"];
    EXPECT_EQ(coverage_summary(report), "Empty: lines 0/0 (-), branches 0/0\n"
                                        "Main: lines 12/14 (85.7%), branches 5/8\n");
}

} // namespace
} // namespace eposp::vm::test
