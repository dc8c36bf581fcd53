// Tasks of compiled programs: a computation preempted at its safe points (loops and function
// calls) gives the result it gives uninterrupted, the programs of one task run in the order of
// the configuration, and a SINGLE variable that starts TRUE releases its task once.

#include "runtime_harness.hpp"

namespace eposp::vm::test {
namespace {

using namespace std::chrono_literals;

// Work sums a function of 2000 values; Tick, every 50 µs at a higher priority, interrupts it
// when instructions take time.
constexpr const char* kPreempted = R"(
FUNCTION Mix : DINT
  VAR_INPUT x : DINT; END_VAR
  Mix := (x * 7919) MOD 1000 - x / 3;
END_FUNCTION
PROGRAM Work
  VAR i : DINT; sum : DINT; done : DINT; END_VAR
  sum := 0;
  FOR i := 1 TO 2000 DO sum := sum + Mix(i); END_FOR;
  done := done + 1;
END_PROGRAM
PROGRAM Ticker
  VAR ticks : DINT; END_VAR
  ticks := ticks + 1;
END_PROGRAM
CONFIGURATION Config0
  RESOURCE Res0 ON PLC
    TASK Slow(INTERVAL := T#100ms, PRIORITY := 2);
    TASK Tick(INTERVAL := T#1ms, PRIORITY := 1);
    PROGRAM W WITH Slow : Work;
    PROGRAM T WITH Tick : Ticker;
  END_RESOURCE
END_CONFIGURATION
)";

TEST(CompiledTasks, PreemptedComputationGivesTheUninterruptedResult) {
    RuntimeHarness instant;
    ASSERT_EQ(instant.load(kPreempted), "");
    ASSERT_FALSE(instant.runtime->start(StartMode::Cold));
    const auto expected = instant.get<std::int32_t>("W.sum");

    RuntimeConfig config;
    config.cost.ns_per_instruction = 100;
    RuntimeHarness h(config);
    ASSERT_EQ(h.load(kPreempted), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(50ms);
    const auto slow = *h.runtime->task_index("Slow");
    const auto tick = *h.runtime->task_index("Tick");
    ASSERT_EQ(h.runtime->statistics(slow).cycles, 1u);
    EXPECT_EQ(h.get<std::int32_t>("W.sum"), expected);
    // Work's cycle took milliseconds, so Tick ran many times inside it, never overrunning.
    EXPECT_GT(h.runtime->statistics(slow).execution_last, 1ms);
    EXPECT_EQ(h.runtime->statistics(tick).cycles, 50u);
    EXPECT_EQ(h.runtime->statistics(tick).overruns, 0u);
    EXPECT_TRUE(h.errors.empty());
}

TEST(CompiledTasks, ProgramsOfOneTaskRunInConfigurationOrder) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(R"(
PROGRAM First VAR_EXTERNAL step : DINT; END_VAR step := step * 10 + 1; END_PROGRAM
PROGRAM Second VAR_EXTERNAL step : DINT; END_VAR step := step * 10 + 2; END_PROGRAM
CONFIGURATION Config0
  VAR_GLOBAL step : DINT; END_VAR
  RESOURCE Res0 ON PLC
    TASK Main(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM B WITH Main : Second;
    PROGRAM A WITH Main : First;
  END_RESOURCE
END_CONFIGURATION
)"),
              "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(1ms);
    EXPECT_EQ(h.get<std::int32_t>("Config0.step"), 2121);
}

TEST(CompiledTasks, SingleVariableStartingTrueReleasesItsTaskOnce) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(R"(
PROGRAM Count VAR_EXTERNAL runs : DINT; END_VAR runs := runs + 1; END_PROGRAM
CONFIGURATION Config0
  VAR_GLOBAL go : BOOL := TRUE; runs : DINT; END_VAR
  RESOURCE Res0 ON PLC
    TASK OnGo(SINGLE := go, PRIORITY := 0);
    PROGRAM C WITH OnGo : Count;
  END_RESOURCE
END_CONFIGURATION
)"),
              "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(10ms);
    EXPECT_EQ(h.get<std::int32_t>("Config0.runs"), 1);
}

} // namespace
} // namespace eposp::vm::test
