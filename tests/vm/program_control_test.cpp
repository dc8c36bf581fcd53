// Program Control 0x5F51 as the device uses it: loading with its refusals, cold, warm and hot
// start against a retain file, periodic and final saves of the RETAIN variables, stop.

#include "eposp/test/test_directory.hpp"
#include "runtime_harness.hpp"

#include <filesystem>
#include <fstream>

namespace eposp::vm::test {
namespace {

using namespace std::chrono_literals;

// Runs in the default 10 ms task: one kept and one lost counter, both from 100.
constexpr const char* kCounters = R"(
PROGRAM Main
  VAR RETAIN kept : DINT := 100; END_VAR
  VAR lost : DINT := 100; END_VAR
  kept := kept + 1;
  lost := lost + 1;
END_PROGRAM
)";

class ProgramControl : public ::testing::Test {
protected:
    ProgramControl() : dir_(eposp::test::test_directory()) {}

    RuntimeConfig with_retain(core::Duration save_interval = {}) const {
        RuntimeConfig config;
        config.retain_file = retain_file();
        config.retain_save_interval = save_interval;
        return config;
    }
    std::filesystem::path retain_file() const { return dir_ / "retain.bin"; }

    // Five cycles (0..40 ms) of kCounters from a start in `mode`, then stop.
    void run_counters(RuntimeHarness& h, StartMode mode) {
        ASSERT_EQ(h.load(kCounters), "");
        ASSERT_FALSE(h.runtime->start(mode));
        h.loop.run_for(45ms);
        h.runtime->stop();
    }

private:
    std::filesystem::path dir_;
};

TEST_F(ProgramControl, StartingWithoutAProgramIsRefused) {
    RuntimeHarness h;
    EXPECT_EQ(h.runtime->state(), ProgramState::NotLoaded);
    EXPECT_EQ(h.runtime->start(StartMode::Cold)->message, "no program is loaded");
}

// CiA 302-3 "clear program": the program stops, saves its RETAIN variables and is gone.
TEST_F(ProgramControl, UnloadStopsAndForgetsTheProgram) {
    RuntimeHarness h(with_retain());
    ASSERT_EQ(h.load(kCounters), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(25ms);
    h.runtime->unload();
    EXPECT_EQ(h.runtime->state(), ProgramState::NotLoaded);
    EXPECT_FALSE(h.runtime->read("Main.kept"));
    EXPECT_TRUE(std::filesystem::exists(retain_file()));
    h.loop.run_for(25ms); // no task runs any more
    EXPECT_EQ(h.runtime->start(StartMode::Cold)->message, "no program is loaded");
    ASSERT_EQ(h.load(kCounters), ""); // a program loads again
    ASSERT_FALSE(h.runtime->start(StartMode::Warm));
    h.loop.run_for(5ms);
    EXPECT_EQ(*h.runtime->read("Main.kept"), "104");
}

TEST_F(ProgramControl, StateAndObjectValueFollowStartAndStop) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(kCounters), "");
    EXPECT_EQ(h.runtime->state(), ProgramState::Stopped);
    EXPECT_EQ(h.runtime->program_control(), 0);
    for (const StartMode mode : {StartMode::Cold, StartMode::Warm, StartMode::Hot}) {
        ASSERT_FALSE(h.runtime->start(mode));
        EXPECT_EQ(h.runtime->state(), ProgramState::Running);
        EXPECT_EQ(h.runtime->program_control(), static_cast<std::uint16_t>(mode));
        EXPECT_EQ(h.runtime->start(mode)->message, "the program is already running; stop it first");
        EXPECT_EQ(h.runtime->load(*RuntimeHarness::compile_st(kCounters))->message,
                  "a program is running; stop it before loading another");
        h.runtime->stop();
        EXPECT_EQ(h.runtime->program_control(), 0);
    }
}

TEST_F(ProgramControl, ProgramWithMoreRetainDataThanTheControllerHoldsIsRefused) {
    RuntimeConfig config;
    config.retain_capacity = 16;
    RuntimeHarness h(config);
    EXPECT_EQ(h.load("PROGRAM Main VAR RETAIN big : ARRAY[1..5] OF DINT; END_VAR END_PROGRAM"),
              "the program declares 20 bytes of RETAIN variables, the controller holds 16");
    EXPECT_EQ(h.runtime->state(), ProgramState::NotLoaded);
}

TEST_F(ProgramControl, LocatedVariablesOutsideTheImageOrTheMarkersAreRefused) {
    RuntimeHarness h;
    EXPECT_EQ(h.load("PROGRAM Main VAR x AT %IW200 : INT; END_VAR END_PROGRAM"),
              "%I400 is outside the process image (bytes 0..223 of the EPOS P)");
    EXPECT_EQ(h.load("PROGRAM Main VAR x AT %MD300 : DINT; END_VAR END_PROGRAM"),
              "%M1200 is outside the marker area (bytes 0..1023 of the EPOS P)");
}

TEST_F(ProgramControl, ColdStartGivesEveryVariableItsInitialValue) {
    RuntimeHarness first(with_retain());
    run_counters(first, StartMode::Cold);
    RuntimeHarness h(with_retain());
    ASSERT_EQ(h.load(kCounters), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    // The first cycle has run at the start.
    EXPECT_EQ(h.get<std::int32_t>("Main.kept"), 101);
    EXPECT_EQ(h.get<std::int32_t>("Main.lost"), 101);
}

TEST_F(ProgramControl, WarmAndHotStartKeepTheRetainVariablesOnly) {
    for (const StartMode mode : {StartMode::Warm, StartMode::Hot}) {
        std::filesystem::remove(retain_file());
        RuntimeHarness first(with_retain());
        run_counters(first, StartMode::Cold); // saves kept = 105 at the stop
        RuntimeHarness h(with_retain());
        ASSERT_EQ(h.load(kCounters), "");
        ASSERT_FALSE(h.runtime->start(mode));
        EXPECT_EQ(h.get<std::int32_t>("Main.kept"), 106);
        EXPECT_EQ(h.get<std::int32_t>("Main.lost"), 101);
        EXPECT_TRUE(h.errors.empty());
    }
}

TEST_F(ProgramControl, ColdStartValuesReplaceTheStoreAtTheNextSave) {
    RuntimeHarness first(with_retain());
    run_counters(first, StartMode::Cold);
    RuntimeHarness second(with_retain());
    ASSERT_EQ(second.load(kCounters), "");
    ASSERT_FALSE(second.runtime->start(StartMode::Cold));
    second.runtime->stop(); // kept = 101
    RuntimeHarness h(with_retain());
    ASSERT_EQ(h.load(kCounters), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Warm));
    EXPECT_EQ(h.get<std::int32_t>("Main.kept"), 102);
}

TEST_F(ProgramControl, WarmStartOnADamagedStoreIsARetainErrorWithColdValues) {
    RuntimeHarness first(with_retain());
    run_counters(first, StartMode::Cold);
    {
        std::fstream file(retain_file(), std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(17);
        file.put('\x55');
    }
    RuntimeHarness h(with_retain());
    ASSERT_EQ(h.load(kCounters), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Warm));
    EXPECT_EQ(h.get<std::int32_t>("Main.kept"), 101);
    ASSERT_EQ(h.error_codes(), std::vector<std::uint16_t>{error_code::kRetainVariable});
    EXPECT_EQ(h.errors[0].text, "retain variables not restored (retain store checksum "
                                "mismatch); cold start values");
}

TEST_F(ProgramControl, WarmStartOfAnotherVariableLayoutIsARetainErrorWithColdValues) {
    RuntimeHarness first(with_retain());
    run_counters(first, StartMode::Cold);
    RuntimeHarness h(with_retain());
    ASSERT_EQ(h.load("PROGRAM Main VAR RETAIN other : DINT := 7; END_VAR END_PROGRAM"), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Warm));
    EXPECT_EQ(h.get<std::int32_t>("Main.other"), 7);
    EXPECT_EQ(h.error_codes(), std::vector<std::uint16_t>{error_code::kRetainVariable});
}

TEST_F(ProgramControl, PeriodicSavesSurviveAPowerLossWithoutStop) {
    {
        RuntimeHarness lost_power(with_retain(7ms));
        ASSERT_EQ(lost_power.load(kCounters), "");
        ASSERT_FALSE(lost_power.runtime->start(StartMode::Cold));
        lost_power.loop.run_for(33ms); // cycles at 0, 10, 20, 30; saves at 7, 14, 21, 28
    }                                  // destroyed running: no stop, no final save
    RuntimeHarness h(with_retain());
    ASSERT_EQ(h.load(kCounters), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Warm));
    EXPECT_EQ(h.get<std::int32_t>("Main.kept"), 104); // 103 saved at 28 ms, then this cycle
}

TEST_F(ProgramControl, PeriodicSaveWritesOnlyWhenTheRetainedBytesChanged) {
    RuntimeHarness h(with_retain(5ms));
    ASSERT_EQ(h.load(R"(
PROGRAM Main
  VAR RETAIN kept : DINT; END_VAR
  IF kept < 3 THEN kept := kept + 1; END_IF;
END_PROGRAM
)"),
              "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(31ms); // kept reaches 3 at 20 ms, saved at 25 ms
    ASSERT_TRUE(std::filesystem::exists(retain_file()));
    std::filesystem::remove(retain_file());
    h.loop.run_for(30ms);
    EXPECT_FALSE(std::filesystem::exists(retain_file())) << "nothing changed, nothing written";
    ASSERT_FALSE(h.runtime->write_value("Main.kept", std::int32_t{1}));
    h.loop.run_for(5ms);
    EXPECT_TRUE(std::filesystem::exists(retain_file()));
}

TEST_F(ProgramControl, StopEndsTheCyclesAndZeroesTheOutputs) {
    RuntimeHarness h;
    ASSERT_EQ(h.load("PROGRAM Main VAR n AT %QW16 : INT; END_VAR n := n + 1; END_PROGRAM"), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(25ms);
    EXPECT_EQ(h.runtime->process_image().outputs()[32], 3);
    h.runtime->stop();
    h.loop.run_for(50ms);
    EXPECT_EQ(h.get<std::int16_t>("Main.n"), 3);
    EXPECT_EQ(h.runtime->process_image().outputs()[32], 0);
    EXPECT_EQ(h.runtime->statistics(0).cycles, 3u);
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    EXPECT_EQ(h.runtime->statistics(0).cycles, 1u) << "a new run, new statistics";
}

TEST_F(ProgramControl, ARestartBeginsNewStatisticsAndKeepsATasksWatchdog) {
    RuntimeHarness h;
    ASSERT_EQ(h.load("PROGRAM Main VAR n : DINT; END_VAR WHILE n >= 0 DO n := n + 1; END_WHILE; "
                     "END_PROGRAM"),
              "");
    h.runtime->set_watchdog(0, 1000);
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    EXPECT_TRUE(h.runtime->task_faulted(0));
    h.runtime->stop();
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    EXPECT_TRUE(h.runtime->task_faulted(0)) << "the same watchdog stops it again";
    EXPECT_EQ(h.error_codes(),
              (std::vector<std::uint16_t>{error_code::kInterpreter, error_code::kInterpreter}));
    EXPECT_EQ(h.runtime->statistics(0).cycles, 0u);
}

TEST_F(ProgramControl, StopWithHoldKeepsTheOutputs) {
    RuntimeConfig config;
    config.safe_state = SafeState::Hold;
    RuntimeHarness h(config);
    ASSERT_EQ(h.load("PROGRAM Main VAR n AT %QW16 : INT; END_VAR n := n + 1; END_PROGRAM"), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(25ms);
    h.runtime->stop();
    EXPECT_EQ(h.runtime->process_image().outputs()[32], 3);
}

} // namespace
} // namespace eposp::vm::test
