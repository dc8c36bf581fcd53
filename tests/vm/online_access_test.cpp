// Online access while the program runs: reading, writing and forcing variables by path, and
// event tasks released by the rising edge of their SINGLE variable or by the device.

#include "runtime_harness.hpp"

namespace eposp::vm::test {
namespace {

using namespace std::chrono_literals;

constexpr const char* kAxes = R"(
TYPE Axis : STRUCT pos : DINT; vel : INT; END_STRUCT; END_TYPE
PROGRAM Main
  VAR counter : DINT; axis : ARRAY[1..3] OF Axis; out AT %QD24 : DINT; END_VAR
  counter := counter + 1;
  axis[2].pos := axis[2].pos + 10;
  out := counter;
END_PROGRAM
CONFIGURATION Config0
  RESOURCE Res0 ON PLC
    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM Inst0 WITH Fast : Main;
  END_RESOURCE
END_CONFIGURATION
)";

std::int32_t published(RuntimeHarness& h) {
    std::int32_t value;
    std::memcpy(&value, h.runtime->process_image().entry(0xA640, 1)->data(), 4);
    return value;
}

TEST(OnlineAccess, ReadsAndWritesVariablesByPathWhileRunning) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(kAxes), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(4ms); // cycles at 0..4 ms
    EXPECT_EQ(*h.runtime->read("Inst0.counter"), "5");
    EXPECT_EQ(*h.runtime->read("inst0.AXIS[2].pos"), "50");
    ASSERT_FALSE(h.runtime->write_value("Inst0.axis[2].pos", std::int32_t{-1000}));
    h.loop.run_for(1ms);
    EXPECT_EQ(*h.runtime->read("Inst0.axis[2].pos"), "-990");
}

TEST(OnlineAccess, BadPathsAndSizesAreRefusedWithTheReason) {
    RuntimeHarness h;
    EXPECT_EQ(h.runtime->read("Inst0.counter").error(), "no program is loaded");
    ASSERT_EQ(h.load(kAxes), "");
    EXPECT_EQ(h.runtime->read("Inst0.nothing").error(), "Inst0 has no field nothing");
    EXPECT_EQ(h.runtime->write_value("Inst0.axis[4].pos", std::int32_t{1})->message,
              "index 4 outside ARRAY[1..3] OF Axis");
    EXPECT_EQ(h.runtime->write_value("Inst0.counter", std::int16_t{1})->message,
              "Inst0.counter is 4 bytes, not 2");
    EXPECT_EQ(h.runtime->unforce("Inst0.counter")->message, "Inst0.counter is not forced");
}

TEST(OnlineAccess, AccessPathsAreReachedByTheirNameAndReadOnlyOnesRefuseWrites) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(R"(
PROGRAM Main
  VAR counter : DINT; limit : DINT := 10; END_VAR
  IF counter < limit THEN counter := counter + 1; END_IF;
END_PROGRAM
CONFIGURATION Config0
  VAR_ACCESS
    Count : Inst0.counter : DINT READ_ONLY;
    Limit : Res0.Inst0.limit : DINT READ_WRITE;
  END_VAR
  RESOURCE Res0 ON PLC
    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM Inst0 WITH Fast : Main;
  END_RESOURCE
END_CONFIGURATION
)"),
              "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    ASSERT_FALSE(h.runtime->write_value("Limit", std::int32_t{3}));
    h.loop.run_for(5ms);
    EXPECT_EQ(*h.runtime->read("count"), "3");
    EXPECT_EQ(h.runtime->write_value("Count", std::int32_t{0})->message,
              "Count is read-only (a constant or a READ_ONLY access path)");
    EXPECT_EQ(h.runtime->force_value("Count", std::int32_t{0})->message,
              "Count is read-only (a constant or a READ_ONLY access path)");
    ASSERT_FALSE(h.runtime->write_value("Inst0.counter", std::int32_t{0}))
        << "the variable itself stays writable by its own path";
}

TEST(OnlineAccess, ConstantsRefuseWritesAndForces) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(R"(
TYPE Point : STRUCT x, y : DINT; END_STRUCT; END_TYPE
VAR_GLOBAL CONSTANT kListed : DINT := 1; END_VAR
VAR_GLOBAL kVariable : DINT; END_VAR
FUNCTION_BLOCK Gain
  VAR CONSTANT k : DINT := 3; END_VAR
  VAR_OUTPUT y : DINT; END_VAR
  y := k;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR CONSTANT kLimit : DINT := 10; END_VAR
  VAR counter : DINT; gain : Gain; END_VAR
  gain();
  counter := kLimit + kListed + gain.y;
END_PROGRAM
CONFIGURATION Config0
  VAR_GLOBAL CONSTANT kOrigin : Point := (x := 1, y := 2); END_VAR
  RESOURCE Res0 ON PLC
    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM Inst0 WITH Fast : Main;
  END_RESOURCE
END_CONFIGURATION
)"),
              "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    for (const char* path : {"kListed", "Inst0.kLimit", "Config0.kOrigin.y", "Inst0.gain.k"}) {
        EXPECT_EQ(h.runtime->write_value(path, std::int32_t{5})->message,
                  std::string(path) + " is read-only (a constant or a READ_ONLY access path)");
        EXPECT_EQ(h.runtime->force_value(path, std::int32_t{5})->message,
                  std::string(path) + " is read-only (a constant or a READ_ONLY access path)");
    }
    EXPECT_EQ(*h.runtime->read("Inst0.kLimit"), "10");
    EXPECT_FALSE(h.runtime->write_value("kVariable", std::int32_t{5}));
    EXPECT_FALSE(h.runtime->write_value("Inst0.counter", std::int32_t{5}));
    EXPECT_FALSE(h.runtime->write_value("Inst0.gain.y", std::int32_t{5}));
}

TEST(OnlineAccess, AWriteOutsideASubrangeIsRefused) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(R"(
PROGRAM Main
  VAR level : INT(-10..100); small : USINT(1..3); END_VAR
  level := level;
END_PROGRAM
)"),
              "");
    ASSERT_FALSE(h.runtime->write_value("Main.level", std::int16_t{-10}));
    ASSERT_FALSE(h.runtime->write_value("Main.level", std::int16_t{100}));
    EXPECT_EQ(h.runtime->write_value("Main.level", std::int16_t{101})->message,
              "Main.level takes values from -10 to 100 only");
    EXPECT_EQ(h.runtime->force_value("Main.level", std::int16_t{-11})->message,
              "Main.level takes values from -10 to 100 only");
    EXPECT_EQ(h.runtime->write_value("Main.small", std::uint8_t{255})->message,
              "Main.small takes values from 1 to 3 only");
    EXPECT_EQ(*h.runtime->read("Main.level"), "100");
}

TEST(OnlineAccess, ForcedVariableKeepsItsValueAroundEveryCycleUntilUnforced) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(kAxes), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    ASSERT_FALSE(h.runtime->force_value("Inst0.counter", std::int32_t{1000}));
    h.loop.run_for(3ms);
    // Each cycle starts from the forced 1000 and the forced value is back after it.
    EXPECT_EQ(h.get<std::int32_t>("Inst0.counter"), 1000);
    EXPECT_EQ(published(h), 1001);
    ASSERT_FALSE(h.runtime->write_value("Inst0.counter", std::int32_t{5}));
    EXPECT_EQ(h.get<std::int32_t>("Inst0.counter"), 1000) << "a write does not beat a force";
    ASSERT_FALSE(h.runtime->unforce("Inst0.counter"));
    h.loop.run_for(2ms);
    EXPECT_EQ(h.get<std::int32_t>("Inst0.counter"), 1002);
    EXPECT_TRUE(h.runtime->forced().forced().empty());
}

TEST(OnlineAccess, ForcedOutputIsWhatIsPublished) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(kAxes), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    ASSERT_FALSE(h.runtime->force_value("Inst0.out", std::int32_t{-7}));
    h.loop.run_for(2ms);
    EXPECT_EQ(published(h), -7);
    EXPECT_EQ(h.get<std::int32_t>("Inst0.counter"), 3);
    ASSERT_FALSE(h.runtime->force_value("Inst0.axis[2].pos", std::int32_t{3}));
    h.loop.run_for(1ms);
    EXPECT_EQ(*h.runtime->read("Inst0.axis[2].pos"), "3");
}

// Count sets `go` every third cycle; OnGo, the event task on `go`, counts its runs.
constexpr const char* kSingle = R"(
PROGRAM Count
  VAR_EXTERNAL go : BOOL; END_VAR
  VAR n : INT; END_VAR
  n := n + 1;
  go := n MOD 3 = 0;
END_PROGRAM
PROGRAM CountHits
  VAR_EXTERNAL hits : INT; END_VAR
  hits := hits + 1;
END_PROGRAM
CONFIGURATION Config0
  VAR_GLOBAL go : BOOL; hits : INT; END_VAR
  RESOURCE Res0 ON PLC
    TASK Cyc(INTERVAL := T#1ms, PRIORITY := 1);
    TASK OnGo(SINGLE := go, PRIORITY := 0);
    PROGRAM C WITH Cyc : Count;
    PROGRAM H WITH OnGo : CountHits;
  END_RESOURCE
END_CONFIGURATION
)";

TEST(EventTasks, SingleRunsOnceOnEachRisingEdgeOfItsVariable) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(kSingle), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold));
    h.loop.run_for(8ms); // n = 1..9: go rises at 3, 6 and 9
    EXPECT_EQ(h.get<std::int16_t>("Config0.hits"), 3);
    EXPECT_EQ(h.runtime->statistics(*h.runtime->task_index("OnGo")).cycles, 3u);
}

TEST(EventTasks, AnOnlineWriteOrTheDeviceReleasesTheTask) {
    RuntimeHarness h;
    ASSERT_EQ(h.load(kSingle), "");
    ASSERT_FALSE(h.runtime->start(StartMode::Cold)); // n = 1: go FALSE
    ASSERT_FALSE(h.runtime->write_value("Config0.go", true));
    EXPECT_EQ(h.get<std::int16_t>("Config0.hits"), 1);
    h.runtime->raise_event(*h.runtime->task_index("OnGo"));
    EXPECT_EQ(h.get<std::int16_t>("Config0.hits"), 2);
    EXPECT_TRUE(h.errors.empty());
}

} // namespace
} // namespace eposp::vm::test
