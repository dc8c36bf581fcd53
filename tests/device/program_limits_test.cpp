// What `eposp build` accepts, `eposp run` loads: a program at an image limit builds and runs,
// one over it is refused by the compiler with the limit in the message (image_limits.hpp).
#include "eposp_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using testing::HasSubstr;

/// A program with two global lists of `elements` DINTs each and a 1 ms task counting its
/// cycles into the last element of the second.
std::string static_data_program(long elements) {
    const std::string array = "ARRAY[1.." + std::to_string(elements) + "] OF DINT";
    return "VAR_GLOBAL a : " + array + "; END_VAR\nVAR_GLOBAL b : " + array + "; END_VAR\n" +
           "PROGRAM Main\nVAR_EXTERNAL b : " + array + "; END_VAR\nVAR n : DINT; END_VAR\n" +
           "n := n + 1; b[" + std::to_string(elements) + "] := n;\nEND_PROGRAM\n" +
           "CONFIGURATION C\nRESOURCE R ON PLC\nTASK T(INTERVAL := T#1ms, PRIORITY := 1);\n" +
           "PROGRAM Inst WITH T : Main;\nEND_RESOURCE\nEND_CONFIGURATION\n";
}

TEST(ProgramLimits, StaticDataToTheLimitBuildsAndRuns) {
    const std::string source = write_source("big.st", static_data_program(7'864'320)); // 60 MiB
    const std::string image = scratch("big.epx").string();
    const auto built = eposp("build " + source + " -o " + image);
    ASSERT_EQ(built.exit_code, 0) << built.output;
    const auto run = eposp("run " + image + " --for 5ms --watch Inst.n");
    EXPECT_EQ(run.exit_code, 0) << run.output;
    EXPECT_THAT(run.output, HasSubstr("Inst.n = 6")); // at 0, 1, ..., 5 ms
}

TEST(ProgramLimits, StaticDataOverTheLimitIsRefusedByTheCompiler) {
    const std::string source = write_source("huge.st", static_data_program(10'000'000)); // 80 MB
    const auto built = eposp("build " + source + " -o " + scratch("huge.epx").string());
    EXPECT_EQ(built.exit_code, 1);
    EXPECT_THAT(built.output, HasSubstr("needs 80000"));
    EXPECT_THAT(built.output, HasSubstr("the limit is 67108864"));
}

TEST(ProgramLimits, ATaskIntervalBelowOneMillisecondIsRefusedByTheCompiler) {
    const std::string source = write_source(
        "fast.st",
        "PROGRAM Main\nEND_PROGRAM\nCONFIGURATION C\nRESOURCE R ON PLC\n"
        "TASK T(INTERVAL := T#1ns, PRIORITY := 1);\nPROGRAM Inst WITH T : Main;\nEND_RESOURCE\n"
        "END_CONFIGURATION\n");
    const auto built = eposp("build " + source + " -o " + scratch("fast.epx").string());
    EXPECT_EQ(built.exit_code, 1);
    EXPECT_THAT(built.output, HasSubstr(source + ":5:20: error: INTERVAL must be at least 1 ms"));
}

} // namespace
} // namespace eposp::device
