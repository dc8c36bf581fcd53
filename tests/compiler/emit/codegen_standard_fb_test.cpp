// The standard function blocks (IEC 61131-3 ed. 3, 6.6.3.5) compiled from the built-in library
// and run scan by scan on a clock advancing 1 ms per scan.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>
#include <limits>

namespace eposp::compiler::test {
namespace {

constexpr std::int64_t kMs = 1'000'000;

/// Runs one scan with `input` set first.
void scan(StProgram& run, bool input) {
    run.set<bool>("Main.in", input);
    ASSERT_TRUE(run.scans(1)) << run.fault();
}

TEST(Timers, TonDelaysTheRisingEdgeAndFollowsAChangedPt) {
    StProgram run(R"(
PROGRAM Main
VAR in : BOOL; pt : TIME := T#3ms; t : TON; q : BOOL; et : TIME; END_VAR
t(IN := in, PT := pt, Q => q, ET => et);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    scan(run, true); // t = 0
    EXPECT_FALSE(run.get<bool>("Main.q"));
    EXPECT_EQ(run.get<std::int64_t>("Main.et"), 0);
    scan(run, true);
    scan(run, true); // t = 2 ms
    EXPECT_FALSE(run.get<bool>("Main.q"));
    EXPECT_EQ(run.get<std::int64_t>("Main.et"), 2 * kMs);
    scan(run, true); // t = 3 ms
    EXPECT_TRUE(run.get<bool>("Main.q"));
    EXPECT_EQ(run.get<std::int64_t>("Main.et"), 3 * kMs);
    run.set<std::int64_t>("Main.pt", 10 * kMs); // PT raised while running: Q drops again
    scan(run, true);
    EXPECT_FALSE(run.get<bool>("Main.q"));
    EXPECT_EQ(run.get<std::int64_t>("Main.et"), 4 * kMs);
    scan(run, false);
    EXPECT_FALSE(run.get<bool>("Main.q"));
    EXPECT_EQ(run.get<std::int64_t>("Main.et"), 0);
}

TEST(Timers, TofDelaysTheFallingEdge) {
    StProgram run(R"(
PROGRAM Main
VAR in : BOOL; t : TOF; q : BOOL; END_VAR
t(IN := in, PT := T#2ms, Q => q);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    scan(run, true);
    EXPECT_TRUE(run.get<bool>("Main.q"));
    scan(run, false); // falling edge at 1 ms
    EXPECT_TRUE(run.get<bool>("Main.q"));
    scan(run, false);
    EXPECT_TRUE(run.get<bool>("Main.q"));
    scan(run, false); // 2 ms after the edge
    EXPECT_FALSE(run.get<bool>("Main.q"));
}

TEST(Timers, TpGivesAPulseOfPt) {
    StProgram run(R"(
PROGRAM Main
VAR in : BOOL; t : TP; q : BOOL; END_VAR
t(IN := in, PT := T#2ms, Q => q);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    scan(run, true);
    EXPECT_TRUE(run.get<bool>("Main.q"));
    scan(run, false); // the pulse goes on although IN fell
    EXPECT_TRUE(run.get<bool>("Main.q"));
    scan(run, false);
    EXPECT_FALSE(run.get<bool>("Main.q"));
}

TEST(EdgesAndBistables, TriggersAndLatches) {
    StProgram run(R"(
PROGRAM Main
VAR in : BOOL; r : R_TRIG; f : F_TRIG; sr : SR; rs : RS; rises, falls : INT; END_VAR
r(CLK := in);
f(CLK := in);
IF r.Q THEN rises := rises + 1; END_IF;
IF f.Q THEN falls := falls + 1; END_IF;
sr(S1 := in, R := TRUE);
rs(S := in, R1 := TRUE);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    for (bool input : {false, true, true, false, true, false}) {
        scan(run, input);
    }
    EXPECT_EQ(run.get<std::int16_t>("Main.rises"), 2);
    EXPECT_EQ(run.get<std::int16_t>("Main.falls"), 2);
    scan(run, true);
    EXPECT_TRUE(run.get<bool>("Main.sr.Q1"));  // set dominant
    EXPECT_FALSE(run.get<bool>("Main.rs.Q1")); // reset dominant
}

TEST(Counters, CountOnRisingEdges) {
    StProgram run(R"(
PROGRAM Main
VAR in : BOOL; up : CTU; down : CTD_DINT; both : CTUD; loaded : BOOL := TRUE; END_VAR
up(CU := in, R := FALSE, PV := 2);
down(CD := in, LD := loaded, PV := 10);
both(CU := in, CD := FALSE, R := FALSE, LD := FALSE, PV := 3);
loaded := FALSE;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    for (bool input : {false, true, true, false, true, false, true}) {
        scan(run, input);
    }
    EXPECT_EQ(run.get<std::int16_t>("Main.up.CV"), 3);
    EXPECT_TRUE(run.get<bool>("Main.up.Q"));
    EXPECT_EQ(run.get<std::int32_t>("Main.down.CV"), 7);
    EXPECT_EQ(run.get<std::int16_t>("Main.both.CV"), 3);
    EXPECT_TRUE(run.get<bool>("Main.both.QU"));
}

// A counter counts down to the least value of its type and up to the greatest, and no further
// (CTD_LINT stopped one above LINT's least value).
TEST(Counters, StopAtTheLimitsOfTheirType) {
    StProgram run(R"(
PROGRAM Main
VAR in : BOOL; loaded : BOOL := TRUE;
    down : CTD_LINT; down_int : CTD; up : CTUD_ULINT; both : CTUD_DINT; END_VAR
down(CD := in, LD := loaded, PV := LINT#-9223372036854775806);
down_int(CD := in, LD := loaded, PV := -32767);
up(CU := in, CD := FALSE, R := FALSE, LD := loaded, PV := ULINT#18446744073709551614);
both(CU := FALSE, CD := in, R := FALSE, LD := loaded, PV := -2147483647);
loaded := FALSE;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    for (bool input : {false, true, false, true, false, true, false, true}) {
        scan(run, input);
    }
    EXPECT_EQ(run.get<std::int64_t>("Main.down.CV"), std::numeric_limits<std::int64_t>::min());
    EXPECT_EQ(run.get<std::int16_t>("Main.down_int.CV"), -32768);
    EXPECT_EQ(run.get<std::uint64_t>("Main.up.CV"), std::numeric_limits<std::uint64_t>::max());
    EXPECT_EQ(run.get<std::int32_t>("Main.both.CV"), std::numeric_limits<std::int32_t>::min());
}

} // namespace
} // namespace eposp::compiler::test

namespace eposp::compiler::test {
namespace {

TEST(StandardLibrary, EveryStandardFbCompilesWithoutDiagnostics) {
    std::string declarations;
    std::string calls;
    int n = 0;
    for (const char* type :
         {"SR",         "RS",        "R_TRIG",    "F_TRIG",     "CTU",       "CTD",
          "CTUD",       "CTU_DINT",  "CTD_DINT",  "CTUD_DINT",  "CTU_LINT",  "CTD_LINT",
          "CTUD_LINT",  "CTU_UDINT", "CTD_UDINT", "CTUD_UDINT", "CTU_ULINT", "CTD_ULINT",
          "CTUD_ULINT", "TP",        "TON",       "TOF",        "RTC"}) {
        const std::string name = "fb" + std::to_string(n++);
        declarations += name + " : " + type + "; ";
        calls += name + "();\n";
    }
    const std::string text =
        diagnostics_of("PROGRAM Main\nVAR " + declarations + "END_VAR\n" + calls + "END_PROGRAM\n");
    EXPECT_EQ(text, "");
}

TEST(Timers, RtcCountsFromItsPresetDateAndTime) {
    StProgram run(R"(
PROGRAM Main
VAR in : BOOL; clock : RTC; now : DT; END_VAR
clock(IN := in, PDT := DT#2024-01-31-12:00:00, CDT => now);
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    scan(run, true);
    scan(run, true);
    scan(run, true);
    // 2024-01-31T12:00:00 as ns since 1970, plus the 2 ms since IN rose.
    EXPECT_EQ(run.get<std::int64_t>("Main.now"), 1'706'702'400'000'000'000 + 2 * kMs);
    EXPECT_TRUE(run.get<bool>("Main.clock.Q"));
}

} // namespace
} // namespace eposp::compiler::test
