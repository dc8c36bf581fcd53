// The standard FBs of the reference evaluator against IEC 61131-3 ed. 3, tables 43-46 and the
// timers' timing diagrams (figure 15), at the exact boundary cycles. One scan is 1 ms.

#include "eposp/reference/reference_program.hpp"

#include <gtest/gtest.h>

namespace eposp::reference {
namespace {

constexpr std::uint64_t kMs = 1'000'000;

/// `Main` runs `call` once per scan with `in` TRUE in the scans listed by `in_during` (a
/// condition on the scan number n, counted from 0).
ReferenceProgram timer(const std::string& type, const std::string& in_during) {
    ReferenceProgram program("PROGRAM Main\nVAR t : " + type +
                             "; n : INT; in : BOOL; END_VAR\nin := " + in_during +
                             ";\nt(IN := in, PT := T#5ms);\nn := n + 1;\nEND_PROGRAM\n");
    EXPECT_TRUE(program.ok()) << program.errors();
    return program;
}

TEST(ReferenceStandardFb, TpEndsItsPulseAtPtAndClearsEtWhenInHasFallen) {
    auto p = timer("TP", "n = 0");
    ASSERT_TRUE(p.scans(5)); // t = 0 .. 4 ms
    EXPECT_EQ(p.bits("Main.t.Q"), 1u);
    EXPECT_EQ(p.bits("Main.t.ET"), 4 * kMs);
    ASSERT_TRUE(p.scans(1)); // t = 5 ms = t0 + PT, IN FALSE
    EXPECT_EQ(p.bits("Main.t.Q"), 0u);
    EXPECT_EQ(p.bits("Main.t.ET"), 0u);
}

TEST(ReferenceStandardFb, TpHoldsEtAtPtWhileInStaysTrue) {
    auto p = timer("TP", "n < 8");
    ASSERT_TRUE(p.scans(6)); // t = 5 ms
    EXPECT_EQ(p.bits("Main.t.Q"), 0u);
    EXPECT_EQ(p.bits("Main.t.ET"), 5 * kMs);
    ASSERT_TRUE(p.scans(3)); // t = 8 ms, IN FALSE
    EXPECT_EQ(p.bits("Main.t.ET"), 0u);
}

TEST(ReferenceStandardFb, TonSetsQExactlyAtPt) {
    auto p = timer("TON", "n < 8");
    ASSERT_TRUE(p.scans(5)); // t = 4 ms
    EXPECT_EQ(p.bits("Main.t.Q"), 0u);
    EXPECT_EQ(p.bits("Main.t.ET"), 4 * kMs);
    ASSERT_TRUE(p.scans(1)); // t = 5 ms
    EXPECT_EQ(p.bits("Main.t.Q"), 1u);
    EXPECT_EQ(p.bits("Main.t.ET"), 5 * kMs);
    ASSERT_TRUE(p.scans(3)); // t = 8 ms, IN FALSE
    EXPECT_EQ(p.bits("Main.t.Q"), 0u);
    EXPECT_EQ(p.bits("Main.t.ET"), 0u);
}

TEST(ReferenceStandardFb, TofClearsQExactlyPtAfterInFalls) {
    auto p = timer("TOF", "n = 0"); // IN falls at t = 1 ms
    ASSERT_TRUE(p.scans(1));
    EXPECT_EQ(p.bits("Main.t.Q"), 1u);
    EXPECT_EQ(p.bits("Main.t.ET"), 0u);
    ASSERT_TRUE(p.scans(5)); // t = 5 ms
    EXPECT_EQ(p.bits("Main.t.Q"), 1u);
    EXPECT_EQ(p.bits("Main.t.ET"), 4 * kMs);
    ASSERT_TRUE(p.scans(1)); // t = 6 ms
    EXPECT_EQ(p.bits("Main.t.Q"), 0u);
    EXPECT_EQ(p.bits("Main.t.ET"), 5 * kMs);
}

TEST(ReferenceStandardFb, CountersCountRisingEdges) {
    ReferenceProgram p(R"(
PROGRAM Main
  VAR up : CTU; down : CTD; both : CTUD; n : INT; pulse : BOOL; END_VAR
  pulse := n MOD 2 = 0;
  up(CU := pulse, R := FALSE, PV := 3);
  down(CD := pulse, LD := n = 0, PV := 2);
  both(CU := pulse, CD := FALSE, R := FALSE, LD := FALSE, PV := 2);
  n := n + 1;
END_PROGRAM
)");
    ASSERT_TRUE(p.ok()) << p.errors();
    ASSERT_TRUE(p.scans(4)); // rising edges at n = 0 and 2
    EXPECT_EQ(p.bits("Main.up.CV"), 2u);
    EXPECT_EQ(p.bits("Main.up.Q"), 0u);
    EXPECT_EQ(p.bits("Main.down.CV"), 1u); // loaded at n = 0, one decrement at n = 2
    EXPECT_EQ(p.bits("Main.down.Q"), 0u);
    EXPECT_EQ(p.bits("Main.both.CV"), 2u);
    EXPECT_EQ(p.bits("Main.both.QU"), 1u);
    ASSERT_TRUE(p.scans(1)); // n = 4
    EXPECT_EQ(p.bits("Main.up.Q"), 1u);
    EXPECT_EQ(p.bits("Main.down.CV"), 0u);
    EXPECT_EQ(p.bits("Main.down.Q"), 1u);
}

TEST(ReferenceStandardFb, EdgesAndBistables) {
    ReferenceProgram p(R"(
PROGRAM Main
  VAR r : R_TRIG; f : F_TRIG; sr : SR; rs : RS; n : INT; clk : BOOL; rises, falls : INT; END_VAR
  clk := n = 1 OR n = 2;                     (* F, T, T, F *)
  r(CLK := clk); f(CLK := clk);
  IF r.Q THEN rises := rises + 1; END_IF;
  IF f.Q THEN falls := falls + 10 * n; END_IF;
  sr(S1 := TRUE, R := TRUE); rs(S := TRUE, R1 := TRUE);
  n := n + 1;
END_PROGRAM
)");
    ASSERT_TRUE(p.ok()) << p.errors();
    ASSERT_TRUE(p.scans(4));
    EXPECT_EQ(p.bits("Main.rises"), 1u);
    EXPECT_EQ(p.bits("Main.falls"), 30u); // only the fall at n = 3, none on the first call
    EXPECT_EQ(p.bits("Main.sr.Q1"), 1u);  // set dominant
    EXPECT_EQ(p.bits("Main.rs.Q1"), 0u);  // reset dominant
}

} // namespace
} // namespace eposp::reference
