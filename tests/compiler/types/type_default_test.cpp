// Initial values that belong to types (IEC 61131-3 ed. 3, 6.4.2): a type declaration's own
// default, structure member defaults, and the errors in them, reported once.
#include "codegen_harness.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t count = 0;
    for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
        ++count;
    }
    return count;
}

constexpr const char* kTypes = "TYPE\n"
                               "  Mode : (Off, Slow, Fast) := Slow;\n"
                               "  Speed : INT := 100;\n"
                               "  Pct : INT (0..100) := 50;\n"
                               "  Gear : (First, Second) := Gear#Second;\n"
                               "  Axis : STRUCT speed : Speed; mode : Mode; END_STRUCT\n"
                               "END_TYPE\n";

TEST(TypeDefault, VariablesWithoutAnInitializerStartAtTheirTypesDefault) {
    StProgram run(std::string(kTypes) +
                  "VAR_GLOBAL g : Speed; END_VAR\n"
                  "FUNCTION_BLOCK Drive VAR_OUTPUT speed : Speed; END_VAR END_FUNCTION_BLOCK\n"
                  "PROGRAM Main\n"
                  "VAR mode : Mode; speed : Speed; pct : Pct; gear : Gear; axis : Axis;\n"
                  "  speeds : ARRAY[1..3] OF Speed; drive : Drive; END_VAR\n"
                  "END_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(run.get<std::int16_t>("Main.mode"), 1);
    EXPECT_EQ(run.get<std::int16_t>("Main.speed"), 100);
    EXPECT_EQ(run.get<std::int16_t>("Main.pct"), 50);
    EXPECT_EQ(run.get<std::int16_t>("Main.gear"), 1);
    EXPECT_EQ(run.get<std::int16_t>("Main.axis.speed"), 100);
    EXPECT_EQ(run.get<std::int16_t>("Main.axis.mode"), 1);
    EXPECT_EQ(run.get<std::int16_t>("Main.speeds[3]"), 100);
    EXPECT_EQ(run.get<std::int16_t>("Main.drive.speed"), 100);
    EXPECT_EQ(run.get<std::int16_t>("g"), 100);
}

TEST(TypeDefault, AVariablesOwnInitializerWins) {
    StProgram run(std::string(kTypes) +
                  "PROGRAM Main\n"
                  "VAR mode : Mode := Fast; speed : Speed := 7; pct : Pct := 3;\n"
                  "  axis : Axis := (speed := 8); END_VAR\n"
                  "END_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    EXPECT_EQ(run.get<std::int16_t>("Main.mode"), 2);
    EXPECT_EQ(run.get<std::int16_t>("Main.speed"), 7);
    EXPECT_EQ(run.get<std::int16_t>("Main.pct"), 3);
    EXPECT_EQ(run.get<std::int16_t>("Main.axis.speed"), 8);
    EXPECT_EQ(run.get<std::int16_t>("Main.axis.mode"), 1);
}

TEST(TypeDefault, ARenamedTypeWithADefaultIsStillItsBaseType) {
    StProgram run(std::string(kTypes) + "PROGRAM Main\nVAR speed : Speed; i : INT; END_VAR\n"
                                        "i := speed + 1; speed := i;\nEND_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int16_t>("Main.speed"), 101);
}

TEST(TypeDefault, OfAnEnumerationWithItsBaseTypeAfterTheValues) {
    StProgram run("TYPE F : (p := 1, q := 2) DINT := q; END_TYPE\n"
                  "PROGRAM Main\nVAR f : F; size : UDINT; END_VAR\nsize := SIZEOF(f);\n"
                  "END_PROGRAM\n");
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(1));
    EXPECT_EQ(run.get<std::int32_t>("Main.f"), 2);
    EXPECT_EQ(run.get<std::uint32_t>("Main.size"), 4U);
}

struct BadDefault {
    std::string name;
    std::string types;
    std::string message;
};

class TypeDefaultError : public testing::TestWithParam<BadDefault> {};

TEST_P(TypeDefaultError, IsReportedOnceAtTheDefaultEvenIfTheTypeIsUnused) {
    const std::string errors =
        diagnostics_of(GetParam().types + "PROGRAM Main\nVAR x : INT; END_VAR\nEND_PROGRAM\n");
    EXPECT_EQ(occurrences(errors, "error:"), 1U) << errors;
    EXPECT_NE(errors.find(GetParam().message), std::string::npos) << errors;
}

INSTANTIATE_TEST_SUITE_P(
    Refused, TypeDefaultError,
    testing::Values(BadDefault{"ValueOfAnotherEnumeration",
                               "TYPE Other : (x, y, z); END_TYPE\nTYPE E : (a, b) := z; END_TYPE\n",
                               "test.st:2:20: error: the initial value must be a value of E"},
                    BadDefault{"NumberThatIsNoValue", "TYPE E : (a := 1, b := 2) := 5; END_TYPE\n",
                               "test.st:1:30: error: the initial value must be a value of E"},
                    BadDefault{"OutsideTheSubrange", "TYPE Pct : INT (0..100) := 500; END_TYPE\n",
                               "test.st:1:28: error: the value 500 is outside Pct (0..100)"}),
    [](const auto& test) { return test.param.name; });

TEST(StructMemberDefault, ErrorIsReportedOnceForAnArrayOfTheStruct) {
    const std::string errors =
        diagnostics_of("TYPE S : STRUCT m : INT := 1.5; END_STRUCT END_TYPE\n"
                       "PROGRAM Main\nVAR a : ARRAY[1..4] OF S; b : S; END_VAR\nEND_PROGRAM\n");
    EXPECT_EQ(occurrences(errors, "error:"), 1U) << errors;
    // A REAL is no INT: E0301, which names both types (issue 17; was E0313).
    EXPECT_NE(errors.find("test.st:1:28: error:"), std::string::npos) << errors;
    EXPECT_NE(errors.find("[E0301]"), std::string::npos) << errors;
}

} // namespace
} // namespace eposp::compiler::test
