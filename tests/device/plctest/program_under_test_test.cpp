// `eposp test` with a suite that runs one of the user's PROGRAMs cycle by cycle by calling it by
// its name and checks its variables as `P.x` (docs/st-language.md, "Calling a PROGRAM"): the
// user's CONFIGURATION is ignored, so the calls run an instance created for them.
#include "../eposp_command.hpp"

#include <gmock/gmock.h>

namespace eposp::device {
namespace {

using ::testing::HasSubstr;

TEST(EpospTestProgramUnderTest, SuiteCallsTheUsersProgramByItsNameCycleByCycle) {
    const auto program = write_source("sequence.st", "PROGRAM Sequence\n"
                                                     "VAR_INPUT Start : BOOL; END_VAR\n"
                                                     "VAR_OUTPUT Done : BOOL; END_VAR\n"
                                                     "VAR Step : INT; END_VAR\n"
                                                     "    CASE Step OF\n"
                                                     "    0: IF Start THEN Step := 1; END_IF\n"
                                                     "    1, 2: Step := Step + 1;\n"
                                                     "    3: Done := TRUE;\n"
                                                     "    END_CASE\n"
                                                     "END_PROGRAM\n"
                                                     "CONFIGURATION Cell\n"
                                                     "    RESOURCE EposP ON EPOS_P\n"
                                                     "        TASK Fast (INTERVAL := T#1ms, "
                                                     "PRIORITY := 1);\n"
                                                     "        PROGRAM Main WITH Fast : Sequence;\n"
                                                     "    END_RESOURCE\n"
                                                     "END_CONFIGURATION\n");
    const auto suite = write_source(
        "sequence_test.st", "PROGRAM SequenceSuite\n"
                            "VAR cycles : INT; END_VAR\n"
                            "    TEST('StepsToDone');\n"
                            "    Sequence(Start := cycles >= 2);\n"
                            "    cycles := cycles + 1;\n"
                            "    IF cycles = 2 THEN\n"
                            "        AssertEquals_INT(0, Sequence.Step, 'waits for Start');\n"
                            "    ELSIF cycles = 4 THEN\n"
                            "        AssertEquals_INT(2, Sequence.Step, 'one step a cycle');\n"
                            "        AssertFalse(Sequence.Done, 'not yet done');\n"
                            "    ELSIF cycles = 6 THEN\n"
                            "        AssertTrue(Sequence.Done, 'done');\n"
                            "        Sequence.Step := 0;\n"
                            "    ELSIF cycles = 7 THEN\n"
                            "        AssertEquals_INT(1, Sequence.Step, 'restarted');\n"
                            "        TEST_FINISHED();\n"
                            "    END_IF\n"
                            "END_PROGRAM\n");
    const auto result = eposp("test " + program + " " + suite);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("SequenceSuite: 1 passed, 0 failed (")) << result.output;
}

} // namespace
} // namespace eposp::device
