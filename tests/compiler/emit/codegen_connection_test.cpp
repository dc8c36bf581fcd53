// Program connections (IEC 61131-3 ed. 3, 6.8.2): `PROGRAM inst WITH t : P (in := source,
// out => sink)` reads globals and their parts, constants, direct addresses and other programs'
// outputs, and writes globals and direct output or memory addresses, widening implicitly.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

std::string cell_with(const std::string& connections) {
    return R"(
TYPE Pair : STRUCT x : INT; y : DINT; END_STRUCT; END_TYPE
PROGRAM Producer
  VAR_INPUT start : BOOL; END_VAR
  VAR_OUTPUT count : INT; big : LINT; word : WORD; END_VAR
  IF start THEN count := count + 1; END_IF;
  word := INT_TO_WORD(count);
END_PROGRAM
PROGRAM Consumer
  VAR_INPUT n : DINT; b : BOOL; small : SINT; w : DWORD; r : LREAL; END_VAR
  VAR_OUTPUT twice : DINT; flag : BOOL; END_VAR
  VAR seen_w : DWORD; seen_r : LREAL; END_VAR
  twice := n * 2;
  flag := b;
  seen_w := w;
  seen_r := r;
END_PROGRAM
CONFIGURATION Cell
  VAR_GLOBAL g : Pair; arr : ARRAY[1..3] OF DINT; go : BOOL := TRUE; wide : LINT; END_VAR
  VAR_GLOBAL CONSTANT kTen : INT := 10; END_VAR
  RESOURCE Cpu ON PLC
    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM P1 WITH Fast : Producer (start := go);
)" + connections +
           R"(
  END_RESOURCE
END_CONFIGURATION
)";
}

TEST(ProgramConnection, ReadsAnotherProgramsOutputAndWritesAnArrayElement) {
    StProgram run(
        cell_with("    PROGRAM C1 WITH Fast : Consumer (n := P1.count, twice => arr[2]);"));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(3)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("C1.n"), 3) << "INT widened to DINT";
    EXPECT_EQ(run.get<std::int32_t>("Cell.arr[2]"), 6);
}

TEST(ProgramConnection, ReadsAndWritesMembersOfAGlobalStructure) {
    StProgram run(cell_with("    PROGRAM C1 WITH Fast : Consumer (n := g.x, twice => g.y);"));
    ASSERT_TRUE(run.ok()) << run.errors();
    run.set<std::int16_t>("Cell.g.x", 21);
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Cell.g.y"), 42);
}

TEST(ProgramConnection, TakesConstantsAndWidenedLiterals) {
    StProgram run(cell_with(
        "    PROGRAM C1 WITH Fast : Consumer (n := kTen, small := -5, r := 2, twice => wide);"));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int8_t>("C1.small"), -5);
    EXPECT_EQ(run.get<double>("C1.seen_r"), 2.0);
    EXPECT_EQ(run.get<std::int64_t>("Cell.wide"), 20) << "DINT widened to LINT";
}

TEST(ProgramConnection, PassesValuesThroughDirectAddresses) {
    // Programs later in the task read what earlier ones wrote to the output and memory areas;
    // the WORD at %MW10 widens into a DWORD input.
    StProgram run(cell_with(R"(
    PROGRAM P2 WITH Fast : Producer (start := go, word => %MW10);
    PROGRAM C1 WITH Fast : Consumer (b := go, flag => %QX0.0);
    PROGRAM C2 WITH Fast : Consumer (b := %QX0.0, w := %MW10);
)"));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(2)) << run.fault();
    EXPECT_TRUE(run.get<bool>("C2.flag"));
    EXPECT_EQ(run.get<std::uint32_t>("C2.seen_w"), 2U);
}

TEST(ProgramConnection, ReadsAnInputAddressBoundToTheProcessImage) {
    StProgram run(cell_with("    PROGRAM C1 WITH Fast : Consumer (b := %IX0.1, w := %ID4);"));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_EQ(run.image().bindings.size(), 2U);
    EXPECT_EQ(run.image().bindings.front().byte_address, 0U);
    EXPECT_EQ(run.image().bindings.front().bit, 1U);
    EXPECT_EQ(run.image().bindings.back().byte_address, 16U);
}

TEST(ProgramConnection, AValueOutsideASubrangeInputStopsTheTaskNamingTheConnectionsLine) {
    StProgram run(R"(
TYPE Percent : INT (0..100); END_TYPE
PROGRAM Gauge
  VAR_INPUT level : Percent; END_VAR
  VAR_OUTPUT shown : Percent; END_VAR
  shown := level;
END_PROGRAM
CONFIGURATION Cell
  VAR_GLOBAL raw : INT := 50; END_VAR
  RESOURCE Cpu ON PLC
    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM G WITH Fast : Gauge (
      level := raw);
  END_RESOURCE
END_CONFIGURATION
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int16_t>("G.shown"), 50);
    run.set<std::int16_t>("Cell.raw", 101);
    EXPECT_FALSE(run.scans(1));
    EXPECT_EQ(run.fault(), "value out of subrange in G.connections at line 13");
}

struct Refused {
    std::string name;
    std::string connections;
    std::string message;
};

class ProgramConnectionRefused : public testing::TestWithParam<Refused> {};

TEST_P(ProgramConnectionRefused, ReportsTheErrorWhereItIs) {
    const Refused& c = GetParam();
    const std::string errors =
        diagnostics_of(cell_with("    PROGRAM C1 WITH Fast : Consumer (" + c.connections + ");"));
    EXPECT_NE(errors.find(c.message), std::string::npos) << errors;
}

constexpr const char* kInputKinds = "error: an input connects to a global variable (or a part "
                                    "of one), a constant, a direct address or an output of "
                                    "another program";
constexpr const char* kOutputKinds = "error: an output connects to a global variable (or a "
                                     "part of one) or a direct output or memory address";

// The connections start in column 38 of line 24.
INSTANTIATE_TEST_SUITE_P(
    Refused, ProgramConnectionRefused,
    testing::Values(
        Refused{"NarrowingInput", "small := P1.count",
                "test.st:24:47: error: a INT value cannot be used as SINT"},
        Refused{"NarrowingOutput", "twice => g.x",
                "test.st:24:47: error: a DINT value cannot be used as INT"},
        Refused{"OtherTypeInput", "n := P1.word",
                "test.st:24:43: error: a WORD value cannot be used as DINT"},
        Refused{"InputOfAnotherProgram", "b := P1.start",
                std::string("test.st:24:43: ") + kInputKinds},
        Refused{"OutputToAnotherProgram", "twice => P1.count",
                std::string("test.st:24:47: ") + kOutputKinds},
        Refused{"OutputToInputAddress", "flag => %IX0.0",
                std::string("test.st:24:46: ") + kOutputKinds},
        Refused{"OutputToLiteral", "flag => TRUE", std::string("test.st:24:46: ") + kOutputKinds},
        Refused{"OutputToConstant", "n := 1, twice => kTen",
                "test.st:24:55: error: 'twice' cannot be connected to a constant"},
        Refused{"FunctionCall", "n := ABS(3)", std::string("test.st:24:43: ") + kInputKinds},
        Refused{"Expression", "n := g.y + 1", std::string("test.st:24:43: ") + kInputKinds},
        Refused{"UnknownGlobal", "n := nowhere",
                "test.st:24:43: error: undeclared identifier 'nowhere'"},
        Refused{"UnknownMember", "n := g.z", "test.st:24:45: error: 'Pair' has no member 'z'"},
        Refused{"UnknownProgram", "n := P9.count",
                "test.st:24:43: error: undeclared identifier 'P9'"},
        Refused{"NotAnInput", "twice := 1",
                "test.st:24:38: error: 'Consumer' has no input of that name"}),
    [](const auto& c) { return c.param.name; });

} // namespace
} // namespace eposp::compiler::test
