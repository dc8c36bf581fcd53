// `eposp build`, `dump`, `run` and `bench` as a user meets them: ST files to an image and back
// to text, a program's tasks run in virtual time, the benchmark programs scanned.
#include "compile_program.hpp"
#include "eposp/vm/image_format.hpp"
#include "eposp_command.hpp"

#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using testing::HasSubstr;
using testing::Not;

// Counts its cycles in a 1 ms task and divides by zero once `fail` is set.
constexpr const char* kCounter = "PROGRAM Main\n"
                                 "  VAR_EXTERNAL total : DINT; END_VAR\n"
                                 "  VAR count : DINT; fail : BOOL; zero : DINT; END_VAR\n"
                                 "  count := count + 1;\n"
                                 "  total := total + 2;\n"
                                 "  IF fail THEN\n"
                                 "    count := count / zero;\n"
                                 "  END_IF;\n"
                                 "END_PROGRAM\n"
                                 "CONFIGURATION Config0\n"
                                 "  VAR_GLOBAL total : DINT; END_VAR\n"
                                 "  RESOURCE Res0 ON PLC\n"
                                 "    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);\n"
                                 "    PROGRAM Inst0 WITH Fast : Main;\n"
                                 "  END_RESOURCE\n"
                                 "END_CONFIGURATION\n";

TEST(BuildCommand, WritesAnImageThatDumpDisassembles) {
    const std::string source = write_source("counter.st", kCounter);
    const std::string image = scratch("counter.epx").string();
    const auto built = eposp("build " + source + " -o " + image);
    ASSERT_EQ(built.exit_code, 0) << built.output;
    EXPECT_THAT(built.output, HasSubstr(image));
    const auto dumped = eposp("dump " + image);
    EXPECT_EQ(dumped.exit_code, 0) << dumped.output;
    EXPECT_THAT(dumped.output, HasSubstr("PROGRAM Main"));
    EXPECT_THAT(dumped.output, HasSubstr("Fast"));
    EXPECT_THAT(dumped.output, HasSubstr("Inst0 : Main"));
}

TEST(BuildCommand, WithoutOutputWritesBesideTheFirstFile) {
    const std::string source = write_source("counter.st", kCounter);
    const auto built = eposp("build " + source);
    ASSERT_EQ(built.exit_code, 0) << built.output;
    EXPECT_TRUE(std::filesystem::exists(scratch("counter.epx")));
}

TEST(BuildCommand, ProgramWithErrorsWritesNothingAndExitsWithOne) {
    const std::string source = write_source(
        "bad.st", "PROGRAM Main\n  VAR x : INT; END_VAR\n  x := 'text';\nEND_PROGRAM\n");
    const auto built = eposp("build " + source + " -o " + scratch("bad.epx").string());
    EXPECT_EQ(built.exit_code, 1);
    EXPECT_THAT(built.output, HasSubstr(source + ":3:"));
    EXPECT_FALSE(std::filesystem::exists(scratch("bad.epx")));
}

TEST(DumpCommand, CorruptImageIsRefusedWithTheReason) {
    const std::string source = write_source("counter.st", kCounter);
    const std::string image = scratch("counter.epx").string();
    ASSERT_EQ(eposp("build " + source + " -o " + image).exit_code, 0);
    std::filesystem::resize_file(image, 100);
    const auto dumped = eposp("dump " + image);
    EXPECT_EQ(dumped.exit_code, 1);
    EXPECT_THAT(dumped.output, HasSubstr("eposp dump: error: " + image + ": image size mismatch"));
}

// An image is outside input: its names reach the terminal, so the verifier refuses one that is
// not printable, and the error names the file.
TEST(DumpCommand, ImageWithAnEscapeSequenceInANameIsRefusedNamingTheFile) {
    vm::Image image = compile_program(kCounter);
    ASSERT_FALSE(image.pous.empty());
    image.pous.front().name = "Main\x1b[2J";
    const auto path = scratch("escape.epx");
    const auto bytes = vm::write_image(image);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    for (const char* command : {"dump ", "run "}) {
        const auto result = eposp(command + path.string());
        EXPECT_EQ(result.exit_code, 1) << result.output;
        EXPECT_THAT(result.output, HasSubstr(path.string() + ": POU 0: name is not printable"));
        EXPECT_THAT(result.output, Not(HasSubstr("\x1b")));
    }
}

TEST(RunCommand, RunsTheTaskAtItsIntervalForTheDuration) {
    const std::string source = write_source("counter.st", kCounter);
    const auto result =
        eposp("run " + source + " --for 10ms --watch Inst0.count --watch Config0.total");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Fast: 11 cycles, every 1ms (priority 0)"));
    EXPECT_THAT(result.output, HasSubstr("Inst0.count = 11"));
    EXPECT_THAT(result.output, HasSubstr("Config0.total = 22"));
}

TEST(RunCommand, ImageAndSourcesRunAlike) {
    const std::string source = write_source("counter.st", kCounter);
    const std::string image = scratch("counter.epx").string();
    ASSERT_EQ(eposp("build " + source + " -o " + image).exit_code, 0);
    const auto from_image = eposp("run " + image + " --for 5ms --watch Inst0.count");
    const auto from_source = eposp("run " + source + " --for 5ms --watch Inst0.count");
    EXPECT_EQ(from_image.exit_code, 0) << from_image.output;
    EXPECT_EQ(from_image.output, from_source.output);
}

TEST(RunCommand, RunTimeErrorStopsTheTaskNamingThePouAndLine) {
    const std::string source = write_source(
        "failing.st", std::string(kCounter).replace(std::string(kCounter).find("fail : BOOL"), 11,
                                                    "fail : BOOL := TRUE"));
    const auto result = eposp("run " + source + " --for 10ms");
    EXPECT_EQ(result.exit_code, 3) << "the program ran into an error";
    EXPECT_THAT(result.output, HasSubstr("Fast: stopped after 0 cycles: division by zero in Main "
                                         "at line 7"));
    const auto interpreted = eposp("run " + source + " --for 10ms --engine interpreter");
    EXPECT_EQ(interpreted.output, result.output);
}

TEST(RunCommand, PrintsEachTasksTimingUnderTheCostModel) {
    const std::string source = write_source("counter.st", kCounter);
    const auto result = eposp("run " + source + " --for 10ms --ns-per-instruction 100");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    // The cycle due at 10 ms ends after it: ten complete cycles of 4 instructions.
    EXPECT_THAT(result.output, HasSubstr("Fast: 10 cycles, every 1ms (priority 0)"));
    EXPECT_THAT(result.output,
                HasSubstr("execution last 400ns min 400ns avg 400ns max 400ns, jitter last "
                          "0s max 0s, 0 overruns, 4 instructions in the last cycle"));
}

TEST(RunCommand, WithoutACostModelSaysTimeIsNotModelledInsteadOfZero) {
    const std::string source = write_source("counter.st", kCounter);
    const auto result = eposp("run " + source + " --for 10ms");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Fast: 11 cycles, every 1ms (priority 0)\n    4 "
                                         "instructions in the last cycle; execution time not "
                                         "modelled (--ns-per-instruction N gives each "
                                         "instruction N ns)\n"));
    EXPECT_THAT(result.output, Not(HasSubstr("execution last")));
    EXPECT_THAT(result.output, Not(HasSubstr("jitter")));
}

TEST(RunCommand, OverrunsAreReportedAsTimerTaskErrors) {
    const std::string source = write_source("counter.st", kCounter);
    const auto result = eposp("run " + source + " --for 3ms --ns-per-instruction 300000");
    EXPECT_EQ(result.exit_code, 3) << "overruns are errors of the run: " << result.output;
    // 1.2 ms per cycle in a 1 ms task: the release at 1 ms finds the first cycle running.
    EXPECT_THAT(result.output, HasSubstr("error 0x6183 at 1ms: task Fast still running when its "
                                         "next cycle was due; cycle skipped"));
    EXPECT_THAT(result.output, HasSubstr("2 overruns")); // at 1 and 3 ms
}

TEST(RunCommand, WarmStartContinuesTheRetainVariablesOfTheLastRun) {
    const std::string source = write_source(
        "retain.st", "PROGRAM Main\n  VAR RETAIN n : DINT; END_VAR\n  n := n + 1;\nEND_PROGRAM\n");
    const std::string retain = scratch("retain.bin").string();
    std::filesystem::remove(retain);
    const std::string run = "run " + source + " --for 25ms --watch Main.n --retain " + retain;
    EXPECT_THAT(eposp(run).output, HasSubstr("Main.n = 3"));
    EXPECT_THAT(eposp(run + " --start warm").output, HasSubstr("Main.n = 6"));
    EXPECT_THAT(eposp(run + " --start cold").output, HasSubstr("Main.n = 3"));
}

// EPOS P firmware specification: 0x6310 Retain Variable Error, a run a script must not take for
// a good one.
TEST(RunCommand, RetainStoreOfAnotherProgramIsARetainErrorAndExitsWithThree) {
    const std::string first = write_source(
        "first.st", "PROGRAM Main\n  VAR RETAIN n : DINT; END_VAR\n  n := n + 1;\nEND_PROGRAM\n");
    const std::string second = write_source(
        "second.st", "PROGRAM Main\n  VAR RETAIN n : LINT; END_VAR\n  n := n + 1;\nEND_PROGRAM\n");
    const std::string retain = scratch("retain.bin").string();
    std::filesystem::remove(retain);
    ASSERT_EQ(eposp("run " + first + " --for 5ms --retain " + retain).exit_code, 0);
    const auto result = eposp("run " + second + " --for 5ms --start warm --retain " + retain);
    EXPECT_EQ(result.exit_code, 3) << result.output;
    EXPECT_THAT(result.output, HasSubstr("error 0x6310"));
}

TEST(RunCommand, CtrlCPrintsTheStatisticsSoFarAndExitsWith130) {
    const std::string source = write_source("counter.st", kCounter);
    const auto result =
        eposp_interrupted("run " + source + " --for 1000000s --watch Inst0.count", scratch("out"));
    EXPECT_EQ(result.exit_code, 130) << result.output;
    EXPECT_THAT(result.output, HasSubstr("interrupted after "));
    EXPECT_THAT(result.output, HasSubstr("Fast: "));
    EXPECT_THAT(result.output, HasSubstr("Inst0.count = "));
}

TEST(RunCommand, WatchMayComeBeforeTheFiles) {
    const std::string source = write_source("counter.st", kCounter);
    const auto result = eposp("run --watch Inst0.count " + source + " --for 10ms");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Inst0.count = 11"));
}

TEST(RunCommand, AnImageWithoutTasksSaysThatNothingRan) {
    const std::string source =
        write_source("function.st", "FUNCTION Twice : INT\n  VAR_INPUT x : INT; END_VAR\n"
                                    "  Twice := 2 * x;\nEND_FUNCTION\n");
    const std::string image = scratch("function.epx").string();
    ASSERT_EQ(eposp("build " + source + " -o " + image).exit_code, 0);
    const auto result = eposp("run " + image + " --for 10ms");
    EXPECT_THAT(result.output, HasSubstr("the program has no task: nothing ran"));
}

TEST(RunCommand, WatchShowsCharactersAsLiteralsLikeStrings) {
    const std::string source = write_source(
        "chars.st", "PROGRAM Main\n  VAR c : CHAR := CHAR#'A'; w : WCHAR := WCHAR#\"$263A\";\n"
                    "    nl : CHAR := CHAR#'$N'; s : STRING := 'a$Nb'; n : USINT := 65; END_VAR\n"
                    "  n := n;\nEND_PROGRAM\n");
    const auto result = eposp("run " + source +
                              " --for 1ms --watch Main.c --watch Main.w --watch Main.nl --watch "
                              "Main.s --watch Main.n");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Main.c = 'A'\n"));
    EXPECT_THAT(result.output, HasSubstr("Main.w = \"$263A\"\n"));
    EXPECT_THAT(result.output, HasSubstr("Main.nl = '$0A'\n"));
    EXPECT_THAT(result.output, HasSubstr("Main.s = 'a$0Ab'\n"));
    EXPECT_THAT(result.output, HasSubstr("Main.n = 65\n")) << "a USINT stays a number";
}

// Written as for CODESYS: types without ';' after END_STRUCT, a global variable list used in
// another file without VAR_EXTERNAL, enumeration values as `E_State.ST_IDLE`.
TEST(RunCommand, CodesysStyleFilesCompileAndRun) {
    const std::string globals = write_source("gvl.st", R"(
TYPE E_State : (ST_IDLE := 0, ST_RUN := 10, ST_ERR := 20); END_TYPE
TYPE ST_Axis :
STRUCT
    name : STRING(20) := 'axis';
    pos : LREAL;
    state : E_State := E_State.ST_IDLE;
END_STRUCT
END_TYPE
VAR_GLOBAL CONSTANT
    MAX_AXES : INT := 4;
END_VAR
VAR_GLOBAL
    gCount : DINT;
END_VAR
)");
    const std::string main = write_source("main.st", R"(
PROGRAM Main
VAR axes : ARRAY[1..MAX_AXES] OF ST_Axis; i : INT; END_VAR
FOR i := 1 TO MAX_AXES DO axes[i].pos := axes[i].pos + 1.0; END_FOR
IF axes[1].state = E_State.ST_IDLE THEN gCount := gCount + 1; END_IF
END_PROGRAM
)");
    const auto result = eposp("run " + globals + " " + main +
                              " --for 30ms --watch gCount --watch Main.axes[4].pos");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("gCount = 4"));
    EXPECT_THAT(result.output, HasSubstr("Main.axes[4].pos = 4"));
}

TEST(RunCommand, UnknownWatchPathIsAUserErrorBeforeTheRun) {
    const std::string source = write_source("counter.st", kCounter);
    const auto result = eposp("run " + source + " --watch Inst0.nothing");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp run: error: --watch Inst0.nothing"));
    EXPECT_THAT(result.output, Not(HasSubstr("cycles")));
}

// The README's example, as a user runs it.
TEST(RunCommand, BlinkerExampleFlashesTwiceInASecond) {
    const auto result = eposp("run " + std::string(EPOSP_SOURCE_DIR) +
                              "/examples/plc-basics/blinker.st --for 1s --watch Cell.flashes");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Cyclic: 101 cycles, every 10ms (priority 1)"));
    // TON of 250 ms restarted one cycle after each expiry: the lamp turns on at 250 and 790 ms.
    EXPECT_THAT(result.output, HasSubstr("Cell.flashes = 2"));
}

TEST(RunCommand, ConnectionsExampleFeedsOneProgramFromAnother) {
    const auto result = eposp("run " + std::string(EPOSP_SOURCE_DIR) +
                              "/examples/plc-basics/connections.st --for 50ms --watch Move.steps "
                              "--watch Cell.axis1.target --watch Cell.history[2]");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    // Ticks counts 51 cycles; Move scales its count by 2.5, and Copy passes that on.
    EXPECT_THAT(result.output, HasSubstr("Move.steps = 51\n"));
    EXPECT_THAT(result.output, HasSubstr("Cell.axis1.target = 127\n"));
    EXPECT_THAT(result.output, HasSubstr("Cell.history[2] = 127\n"));
}

// The PLC part of `./eposp.sh demo`.
TEST(PlcDemo, RunsToTheEnd) {
    const auto dir = scratch("demo");
    const auto result =
        test::run_command("EPOSP_DEMO_DIR=" + dir.string() + " " + EPOSP_SOURCE_DIR +
                          "/examples/plc-basics/run.sh " + kEposp + " 2>&1");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("blinker.epx: "));
    EXPECT_THAT(result.output, HasSubstr("CURRENT_TIME() : LINT"));
    EXPECT_THAT(result.output, HasSubstr("Cell.flashes = 4"));
}

TEST(BenchCommand, BenchmarkProgramGivesTheTableResults) {
    const auto result = eposp("bench " + std::string(EPOSP_SOURCE_DIR) +
                              "/tests/compiler/inputs/crc32.st --scans 1000");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("cycles=1000 "));
    EXPECT_THAT(result.output, HasSubstr("result=1099718708 "));
    EXPECT_THAT(result.output, HasSubstr("r=514947.000000 "));
    EXPECT_THAT(result.output, HasSubstr("us_per_scan="));
}

TEST(BenchCommand, BothEnginesGiveTheTableResults) {
    for (const char* engine : {"compiled", "interpreter"}) {
        const auto result = eposp("bench " + std::string(EPOSP_SOURCE_DIR) +
                                  "/tests/compiler/inputs/sieve.st --scans 100 --engine " + engine);
        EXPECT_EQ(result.exit_code, 0) << engine << ": " << result.output;
        EXPECT_THAT(result.output, HasSubstr("cycles=100 ")) << engine;
    }
}

TEST(BenchCommand, CtrlCPrintsTheFiguresOfTheScansDoneAndExitsWith130) {
    const auto result = eposp_interrupted("bench " + std::string(EPOSP_SOURCE_DIR) +
                                              "/tests/compiler/inputs/sieve.st --scans 1000000000",
                                          scratch("out"));
    EXPECT_EQ(result.exit_code, 130) << result.output;
    EXPECT_THAT(result.output, HasSubstr("us_per_scan="));
    EXPECT_THAT(result.output, HasSubstr(" of 1000000000 scans"));
}

TEST(BenchCommand, AFaultOfTheProgramExitsWithThree) {
    const std::string source = write_source(
        "failing.st", std::string(kCounter).replace(std::string(kCounter).find("fail : BOOL"), 11,
                                                    "fail : BOOL := TRUE"));
    const auto result = eposp("bench " + source + " --scans 10");
    EXPECT_EQ(result.exit_code, 3) << result.output;
    EXPECT_THAT(result.output, HasSubstr("division by zero in Main at line 7"));
}

TEST(BenchCommand, UnknownEngineIsRefused) {
    const auto result = eposp("bench " + std::string(EPOSP_SOURCE_DIR) +
                              "/tests/compiler/inputs/sieve.st --engine jit");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("jit not in {compiled,interpreter}"));
}

TEST(BenchCommand, ProgramWithoutCyclicTaskIsAUserError) {
    const std::string source = write_source(
        "event.st", "PROGRAM Main\n  VAR x : INT; END_VAR\n  x := x + 1;\nEND_PROGRAM\n"
                    "CONFIGURATION C\n  VAR_GLOBAL go : BOOL; END_VAR\n  RESOURCE R ON PLC\n"
                    "    TASK E(SINGLE := go, PRIORITY := 1);\n    PROGRAM I WITH E : Main;\n"
                    "  END_RESOURCE\nEND_CONFIGURATION\n");
    const auto result = eposp("bench " + source);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("no cyclic task"));
}

} // namespace
} // namespace eposp::device
