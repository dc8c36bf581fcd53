// Operands and arguments are evaluated from left to right (IEC 61131-3 ed. 3, 7.3.2;
// docs/st-language.md, "POUs and calls"): a variable read before a later operand's call changes
// it (through VAR_IN_OUT, a global, an output) keeps the value it had. Code generation read
// such a variable after the call: `x + Fn(x)` added the x that Fn had incremented.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

constexpr const char* kPous = R"(
VAR_GLOBAL g : INT; gs : STRING; gl : LREAL; END_VAR
FUNCTION Fn : INT
VAR_IN_OUT io : INT; END_VAR
io := io + 1; Fn := io;
END_FUNCTION
FUNCTION Bump : INT
g := g + 1; Bump := g;
END_FUNCTION
FUNCTION SetText : STRING
gs := 'changed'; SetText := 'x';
END_FUNCTION
FUNCTION Overwrite : STRING
gs := 'zzz'; Overwrite := 'p';
END_FUNCTION
FUNCTION SetReal : LREAL
gl := 99.0; SetReal := 1.0;
END_FUNCTION
FUNCTION Out : INT
VAR_OUTPUT o : INT; END_VAR
o := 100; Out := 1;
END_FUNCTION
FUNCTION Pair : INT
VAR_INPUT a, b : INT; END_VAR
Pair := a * 1000 + b;
END_FUNCTION
FUNCTION_BLOCK Sum
VAR_INPUT a, b : INT; END_VAR VAR_OUTPUT r : INT; END_VAR
r := a * 10 + b;
END_FUNCTION_BLOCK
)";

struct Case {
    const char* statement; ///< assigns `r` (INT), `b` (BOOL), `s` (STRING) or `l` (LREAL)
    const char* variable;
    std::int64_t expected; ///< for r and b
};

const Case kCases[] = {
    {"x := 0; r := x + Fn(x);", "r", 1},
    {"x := 5; r := x - Fn(x);", "r", -1},
    {"x := 0; r := x * 10 + Fn(x);", "r", 1},
    {"x := 0; b := x < Fn(x);", "b", 1},
    {"x := 0; IF x < Fn(x) THEN r := 1; ELSE r := 2; END_IF", "r", 1},
    {"x := 0; r := Pair(x, Fn(x));", "r", 1},
    {"x := 0; r := Pair(b := Fn(x), a := x);", "r", 1001},
    {"x := 0; r := ADD(x, Fn(x));", "r", 1},
    {"x := 0; r := MAX(x, Fn(x) - 5);", "r", 0},
    {"x := 0; r := SEL(TRUE, x, Fn(x));", "r", 1},
    {"x := 0; r := arr[x] + Fn(x);", "r", 1},
    {"g := 0; r := g + Bump();", "r", 1},
    {"g := 0; r := Pair(g, Bump());", "r", 1},
    {"y := 0; r := Pair(y, Out(o => y));", "r", 1},
    {"x := 0; sum(a := x, b := Fn(x)); r := sum.r;", "r", 1},
    {"x := 2; r := REAL_TO_INT(INT_TO_REAL(x) ** INT_TO_REAL(Fn(x)));", "r", 8},
};

std::string program(const Case& c) {
    return std::string(kPous) + R"(
PROGRAM Main
VAR x, y, r : INT; b : BOOL; s : STRING; l : LREAL; sum : Sum;
    arr : ARRAY[0..3] OF INT := [0, 10, 20, 30]; END_VAR
)" + c.statement +
           "\nEND_PROGRAM\n";
}

TEST(EvaluationOrder, AVariableIsReadBeforeALaterOperandsCallChangesIt) {
    for (const Case& c : kCases) {
        StProgram run(program(c));
        ASSERT_TRUE(run.ok()) << c.statement << "\n" << run.errors();
        ASSERT_TRUE(run.scans(1)) << c.statement;
        const std::string path = std::string("Main.") + c.variable;
        const std::int64_t value = std::string(c.variable) == "b" ? run.get<std::uint8_t>(path)
                                                                  : run.get<std::int16_t>(path);
        EXPECT_EQ(value, c.expected) << c.statement;
    }
}

TEST(EvaluationOrder, TextsAndRealsAreReadBeforeTheCallToo) {
    StProgram run(std::string(kPous) + R"(
PROGRAM Main
VAR s : STRING; l : LREAL; b : BOOL; END_VAR
gs := 'orig'; s := CONCAT(gs, SetText());
gs := 'orig'; b := gs < Overwrite();
gl := 0.0; l := gl + SetReal();
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get_string("Main.s"), "origx");
    EXPECT_EQ(run.get<double>("Main.l"), 1.0);
    EXPECT_EQ(run.get<std::uint8_t>("Main.b"), 1); // 'orig' < 'p', where 'zzz' is not
}

} // namespace
} // namespace eposp::compiler::test
