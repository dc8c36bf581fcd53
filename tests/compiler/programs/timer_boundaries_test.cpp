// TP, TON and TOF at the exact cycles where their timing diagrams change (IEC 61131-3 ed. 3,
// 6.6.3.5.5, figure 15): each scan runs 1 ms after the previous one, so scan k runs at t = k ms.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>
#include <string>

namespace eposp::compiler::test {
namespace {

constexpr std::int64_t kMs = 1'000'000;

/// A program calling one `timer` with PT = 3 ms on `Main.in`, its outputs in `Main.q`, `Main.et`.
StProgram timer_program(const std::string& timer) {
    return StProgram("PROGRAM Main\nVAR in : BOOL; t : " + timer +
                     "; q : BOOL; et : TIME; END_VAR\n"
                     "t(IN := in, PT := T#3ms, Q => q, ET => et);\nEND_PROGRAM\n");
}

/// Runs one scan with IN = `in` and checks Q and ET after it.
void expect_scan(StProgram& run, bool in, bool q, std::int64_t et_ms) {
    run.set<bool>("Main.in", in);
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<bool>("Main.q"), q);
    EXPECT_EQ(run.get<std::int64_t>("Main.et"), et_ms * kMs);
}

TEST(TimerBoundaries, TpEndingWithInFalseClearsEtInTheSameCall) {
    StProgram run = timer_program("TP");
    ASSERT_TRUE(run.ok()) << run.errors();
    expect_scan(run, true, true, 0);   // t = 0: rising edge, the pulse starts
    expect_scan(run, false, true, 1);  // the pulse goes on although IN fell
    expect_scan(run, false, true, 2);  // t = PT - 1 ms
    expect_scan(run, false, false, 0); // t = PT: the pulse ends and IN is FALSE: ET = 0 at once
    expect_scan(run, false, false, 0);
}

TEST(TimerBoundaries, TpHoldsPtAfterThePulseWhileInStaysTrue) {
    StProgram run = timer_program("TP");
    ASSERT_TRUE(run.ok()) << run.errors();
    expect_scan(run, true, true, 0);
    expect_scan(run, true, true, 1);
    expect_scan(run, true, true, 2);
    expect_scan(run, true, false, 3); // t = PT: the pulse ends, IN still TRUE: ET = PT
    expect_scan(run, true, false, 3); // no new pulse without a new rising edge
    expect_scan(run, false, false, 0);
    expect_scan(run, true, true, 0); // a new rising edge, a new pulse
}

TEST(TimerBoundaries, TpIgnoresARisingEdgeDuringThePulse) {
    StProgram run = timer_program("TP");
    ASSERT_TRUE(run.ok()) << run.errors();
    expect_scan(run, true, true, 0);
    expect_scan(run, false, true, 1);
    expect_scan(run, true, true, 2);  // a rising edge inside the pulse does not restart it
    expect_scan(run, true, false, 3); // ends at the first edge + PT, IN TRUE: ET = PT
}

TEST(TimerBoundaries, TonSetsQExactlyAtPtAndClearsBothWhenInFalls) {
    StProgram run = timer_program("TON");
    ASSERT_TRUE(run.ok()) << run.errors();
    expect_scan(run, false, false, 0);
    expect_scan(run, true, false, 0); // t0: the rising edge starts the delay
    expect_scan(run, true, false, 1);
    expect_scan(run, true, false, 2);  // t0 + PT - 1 ms
    expect_scan(run, true, true, 3);   // t0 + PT: Q rises, ET = PT
    expect_scan(run, true, true, 3);   // ET stays at PT
    expect_scan(run, false, false, 0); // IN falls: Q and ET clear in the same call
    expect_scan(run, true, false, 0);  // a new delay from the new rising edge
    expect_scan(run, false, false, 0); // IN falling before PT: Q never rose
}

TEST(TimerBoundaries, TofClearsQExactlyAtPtAndHoldsEtUntilInRises) {
    StProgram run = timer_program("TOF");
    ASSERT_TRUE(run.ok()) << run.errors();
    expect_scan(run, false, false, 0); // no falling edge before IN was ever TRUE
    expect_scan(run, true, true, 0);   // Q follows IN at once
    expect_scan(run, false, true, 0);  // t0: the falling edge starts the delay
    expect_scan(run, false, true, 1);
    expect_scan(run, false, true, 2);  // t0 + PT - 1 ms
    expect_scan(run, false, false, 3); // t0 + PT: Q falls, ET = PT
    expect_scan(run, false, false, 3); // ET stays at PT while IN stays FALSE
    expect_scan(run, true, true, 0);   // IN rises: Q and ET in the same call
    expect_scan(run, false, true, 0);  // a new delay
    expect_scan(run, true, true, 0);   // IN rising before PT: Q never fell
}

} // namespace
} // namespace eposp::compiler::test
