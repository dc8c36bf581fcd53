// The limits of an image (eposp/vm/image_limits.hpp) are checked when compiling, with the limit
// in the message: what compiles, loads and runs; what would not load does not compile.
#include "codegen_harness.hpp"
#include "eposp/vm/image_limits.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <string>

namespace eposp::compiler::test {
namespace {

using testing::HasSubstr;

/// A PROGRAM calling a chain of `depth` FUNCTIONs, each calling the next: Main.x = depth.
std::string call_chain(int depth) {
    std::string source;
    for (int i = 1; i <= depth; ++i) {
        const std::string callee = i < depth ? "F" + std::to_string(i + 1) + "(n + 1)" : "n";
        source += "FUNCTION F" + std::to_string(i) + " : DINT\nVAR_INPUT n : DINT; END_VAR\nF" +
                  std::to_string(i) + " := " + callee + ";\nEND_FUNCTION\n";
    }
    return source + "PROGRAM Main\nVAR x : DINT; END_VAR\nx := F1(1);\nEND_PROGRAM\n";
}

TEST(ImageLimits, CallsNestingToTheLimitRun) {
    StProgram run(call_chain(static_cast<int>(vm::kMaxCallDepth)));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("Main.x"), static_cast<std::int32_t>(vm::kMaxCallDepth));
}

TEST(ImageLimits, CallsNestingDeeperThanTheLimitAreRefused) {
    EXPECT_THAT(diagnostics_of(call_chain(3000)),
                HasSubstr("error: calls from 'Main' nest 3000 deep; the limit is 256"));
    EXPECT_THAT(diagnostics_of(call_chain(static_cast<int>(vm::kMaxCallDepth) + 1)),
                HasSubstr("error: calls from 'Main' nest 257 deep; the limit is 256"));
}

TEST(ImageLimits, StaticDataToTheLimitRuns) {
    // Two lists of 30 MiB each: 60 MiB of the 64 MiB static data area.
    StProgram run(R"(
VAR_GLOBAL a : ARRAY[0..7864319] OF DINT; END_VAR
VAR_GLOBAL b : ARRAY[0..7864319] OF DINT; END_VAR
PROGRAM Main
VAR_EXTERNAL a, b : ARRAY[0..7864319] OF DINT; END_VAR
a[7864319] := 5; b[7864319] := a[7864319] + 1;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::int32_t>("b[7864319]"), 6);
}

TEST(ImageLimits, StaticDataOverTheLimitIsRefused) {
    EXPECT_THAT(diagnostics_of("VAR_GLOBAL a : ARRAY[0..9999999] OF DINT; END_VAR\n"
                               "VAR_GLOBAL b : ARRAY[0..9999999] OF DINT; END_VAR\n"
                               "PROGRAM Main\nEND_PROGRAM\n"),
                HasSubstr("error: the program's static data (globals, program and FB instances, "
                          "constants) needs 80000"));
    EXPECT_THAT(diagnostics_of("PROGRAM Main\nVAR a, b : ARRAY[0..9999999] OF DINT; END_VAR\n"
                               "END_PROGRAM\n"),
                HasSubstr("test.st:2:5: error: this structure or instance is too large: its data "
                          "exceeds the limit of 67108864 bytes"));
    EXPECT_THAT(diagnostics_of("PROGRAM Main\nVAR a : ARRAY[0..40000000] OF DINT; END_VAR\n"
                               "END_PROGRAM\n"),
                HasSubstr("test.st:2:9: error: this array is too large: its data exceeds the "
                          "limit of 67108864 bytes"));
}

TEST(ImageLimits, TaskStacksOverTheLimitAreRefused) {
    // Each FUNCTION's frame holds its 40 MB array; the task's stack holds every frame.
    EXPECT_THAT(diagnostics_of(R"(
FUNCTION F : DINT
VAR a : ARRAY[0..9999999] OF DINT; END_VAR
F := a[0];
END_FUNCTION
FUNCTION G : DINT
VAR a : ARRAY[0..9999999] OF DINT; END_VAR
G := a[1];
END_FUNCTION
PROGRAM Main
VAR x : DINT; END_VAR
x := F() + G();
END_PROGRAM
)"),
                HasSubstr("; the limit is 67108864"));
}

TEST(ImageLimits, TaskIntervalsBelowOneMillisecondAreRefused) {
    const auto configuration = [](const std::string& interval) {
        return "PROGRAM Main\nEND_PROGRAM\nCONFIGURATION C\nRESOURCE R ON PLC\nTASK T(INTERVAL "
               ":= " +
               interval +
               ", PRIORITY := 1);\nPROGRAM I WITH T : Main;\nEND_RESOURCE\nEND_CONFIGURATION\n";
    };
    EXPECT_THAT(diagnostics_of(configuration("T#1ns")),
                HasSubstr("test.st:5:20: error: INTERVAL must be at least 1 ms"));
    EXPECT_THAT(diagnostics_of(configuration("T#999us")),
                HasSubstr("error: INTERVAL must be at least 1 ms"));
    EXPECT_EQ(diagnostics_of(configuration("T#1ms")), "");
}

} // namespace
} // namespace eposp::compiler::test
