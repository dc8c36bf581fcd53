// CODESYS forms the standard does not have, found in widely used open ST libraries: accepted
// with a warning that names the standard's form.
#include "codegen_harness.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

using testing::HasSubstr;

TEST(CodesysForms, RealLiteralsWithAnExponentButNoPoint) {
    StProgram run(R"(
PROGRAM Main
VAR big, low : REAL; small : LREAL; END_VAR
big := 1E37;
low := -1E38;
small := 2e-3;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<float>("Main.big"), 1e37f);
    EXPECT_EQ(run.get<float>("Main.low"), -1e38f);
    EXPECT_EQ(run.get<double>("Main.small"), 2e-3);
    EXPECT_THAT(run.errors(), HasSubstr("test.st:4:8: warning: real literal '1E37' has no "
                                        "decimal point, which IEC 61131-3 (6.3.2) requires"));
}

TEST(CodesysForms, TypedRealLiteralsWithAnExponentButNoPoint) {
    StProgram run(R"(
PROGRAM Main
VAR big : REAL; small : LREAL; n : INT; END_VAR
big := REAL#1E37;
small := LREAL#-2e-3;
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<float>("Main.big"), 1e37f);
    EXPECT_EQ(run.get<double>("Main.small"), -2e-3);
    EXPECT_THAT(run.errors(), HasSubstr("test.st:4:8: warning: real literal 'REAL#1E37' has no "
                                        "decimal point, which IEC 61131-3 (6.3.2) requires"));
    // An integer type takes no exponent.
    EXPECT_THAT(diagnostics_of("PROGRAM Main VAR n : INT; END_VAR n := INT#1E3; END_PROGRAM"),
                HasSubstr("error: INT# needs an integer value, not '1E3'"));
}

TEST(CodesysForms, OnAndOffAreNamesOutsideAResource) {
    StProgram run(R"(
PROGRAM Main
VAR ON, OFF : BOOL; count : INT; END_VAR
ON := NOT ON;
OFF := NOT ON;
IF ON THEN count := count + 1; END_IF;
END_PROGRAM
CONFIGURATION Cell
  RESOURCE Cpu ON PLC
    TASK Cycle(INTERVAL := T#10ms, PRIORITY := 1);
    PROGRAM Inst WITH Cycle : Main;
  END_RESOURCE
END_CONFIGURATION
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(3)) << run.fault();
    EXPECT_TRUE(run.get<bool>("Inst.ON"));
    EXPECT_FALSE(run.get<bool>("Inst.OFF"));
    EXPECT_EQ(run.get<std::int16_t>("Inst.count"), 2);
    EXPECT_THAT(run.errors(), HasSubstr("warning: 'ON' is a keyword of IEC 61131-3"));
}

TEST(CodesysForms, ArrayInitialValuesWithoutBrackets) {
    StProgram run(R"(
TYPE Triple : ARRAY[0..2] OF INT := 4, 5, 6; END_TYPE
PROGRAM Main
VAR SX : ARRAY[1..7] OF BYTE := 1,3,7,15; t : Triple; r : ARRAY[0..3] OF INT := 2(9), 1; END_VAR
END_PROGRAM
)");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1)) << run.fault();
    EXPECT_EQ(run.get<std::uint8_t>("Main.SX[1]"), 1);
    EXPECT_EQ(run.get<std::uint8_t>("Main.SX[4]"), 15);
    EXPECT_EQ(run.get<std::uint8_t>("Main.SX[5]"), 0);
    EXPECT_EQ(run.get<std::int16_t>("Main.t[2]"), 6);
    EXPECT_EQ(run.get<std::int16_t>("Main.r[1]"), 9);
    EXPECT_EQ(run.get<std::int16_t>("Main.r[2]"), 1);
    EXPECT_THAT(run.errors(), HasSubstr("test.st:4:33: warning: array initial values without "
                                        "brackets are a CODESYS V2 form"));
}

} // namespace
} // namespace eposp::compiler::test
