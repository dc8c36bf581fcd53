// VAR_ACCESS (IEC 61131-3 ed. 3, 6.5.2.2): each access path is a symbol named after it, READ_ONLY
// unless declared READ_WRITE; an unknown path or another type is a compile error.
#include "codegen_harness.hpp"
#include "eposp/compiler/compiler.hpp"

#include <gtest/gtest.h>

namespace eposp::compiler::test {
namespace {

std::string cell_with(const std::string& access) {
    return R"(
TYPE Reading : STRUCT level : INT; ok : BOOL; END_STRUCT; END_TYPE
PROGRAM Main
  VAR count : INT; setpoint : DINT := 5; r : Reading; END_VAR
  VAR CONSTANT k : INT := 1; END_VAR
  count := count + k;
  r.level := count * 2;
END_PROGRAM
CONFIGURATION Cell
  VAR_GLOBAL total : DINT := 7; END_VAR
  VAR_GLOBAL CONSTANT kMax : INT := 3; END_VAR
  VAR_ACCESS
)" + access +
           R"(
  END_VAR
  RESOURCE Res0 ON PLC
    TASK Fast(INTERVAL := T#1ms, PRIORITY := 0);
    PROGRAM Inst0 WITH Fast : Main;
  END_RESOURCE
END_CONFIGURATION
)";
}

std::optional<vm::Image> compile_text(const std::string& text) {
    SourceManager sources;
    const FileId file = sources.add("test.st", text);
    Diagnostics diagnostics;
    return compile(sources, {&file, 1}, diagnostics);
}

const vm::Symbol* symbol(const vm::Image& image, std::string_view path) {
    for (const vm::Symbol& candidate : image.symbols) {
        if (candidate.path == path) {
            return &candidate;
        }
    }
    return nullptr;
}

TEST(AccessPath, IsASymbolNamedAfterItReadOnlyByDefault) {
    const auto image = compile_text(cell_with(R"(
    Cycles : Res0.Inst0.count : INT READ_ONLY;
    Target : Inst0.setpoint : DINT READ_WRITE;
    Level : Inst0.r.level : INT;
    Sum : total : DINT READ_WRITE;
    Input : %IW4 : WORD;
)"));
    ASSERT_TRUE(image);
    const vm::Symbol* count = symbol(*image, "Inst0");
    ASSERT_NE(count, nullptr);
    const vm::Symbol* cycles = symbol(*image, "Cycles");
    const vm::Symbol* target = symbol(*image, "Target");
    const vm::Symbol* level = symbol(*image, "Level");
    const vm::Symbol* sum = symbol(*image, "Sum");
    ASSERT_TRUE(cycles && target && level && sum);
    EXPECT_TRUE(cycles->read_only);
    EXPECT_FALSE(target->read_only);
    EXPECT_TRUE(level->read_only);
    EXPECT_FALSE(sum->read_only);
    EXPECT_EQ(cycles->offset, count->offset) << "count is Main's first variable";
    EXPECT_EQ(sum->offset, symbol(*image, "Cell.total")->offset);
    const vm::Symbol* input = symbol(*image, "Input");
    ASSERT_NE(input, nullptr);
    ASSERT_EQ(image->bindings.size(), 1U);
    EXPECT_EQ(image->bindings.front().offset, input->offset) << "%IW4 is bound where it is read";
    EXPECT_EQ(image->bindings.front().byte_address, 8U);
}

TEST(AccessPath, ReadsTheVariableItNames) {
    StProgram run(cell_with(R"(
    Cycles : Inst0.count : INT;
    Sensor : Inst0.r : Reading;
    Sum : total : DINT;
)"));
    ASSERT_TRUE(run.ok()) << run.errors();
    ASSERT_TRUE(run.scans(3));
    EXPECT_EQ(run.get<std::int16_t>("Cycles"), 3);
    EXPECT_EQ(run.get<std::int16_t>("Sensor.level"), 6);
    EXPECT_EQ(run.get<std::int32_t>("sum"), 7);
}

struct Refused {
    std::string name;
    std::string access;
    std::string message;
};

class AccessPathRefused : public testing::TestWithParam<Refused> {};

TEST_P(AccessPathRefused, ReportsTheErrorWhereItIs) {
    const Refused& c = GetParam();
    StProgram run(cell_with(c.access));
    EXPECT_FALSE(run.ok());
    EXPECT_NE(run.errors().find(c.message), std::string::npos) << run.errors();
}

INSTANTIATE_TEST_SUITE_P(
    Refused, AccessPathRefused,
    testing::Values(
        Refused{"OtherType", "    A : Inst0.count : DINT;",
                "test.st:13:23: error: the access path 'A' is a INT, not a DINT"},
        Refused{"DirectAddressOfAnotherType", "    A : %IW4 : INT;",
                "test.st:13:16: error: the access path 'A' is a WORD, not a INT"},
        Refused{"UnknownVariable", "    A : Inst0.nothing : INT;",
                "test.st:13:5: error: unknown access path 'Inst0.nothing'"},
        Refused{"UnknownInstance", "    A : Inst9.count : INT;",
                "unknown access path 'Inst9.count'"},
        Refused{"UnknownResource", "    A : Res9.Inst0.count : INT;",
                "unknown access path 'Res9.Inst0.count'"},
        Refused{"InternalOfAStructure", "    A : Inst0.r.level.x : INT;",
                "unknown access path 'Inst0.r.level.x'"},
        Refused{"WritableConstant", "    A : kMax : INT READ_WRITE;",
                "test.st:13:5: error: the access path 'A' names a constant: it can only be "
                "READ_ONLY"},
        Refused{"NameOfAnInstance", "    Inst0 : Inst0.count : INT;",
                "'Inst0' is already the name of a program instance or an access path"},
        Refused{"NameTwice", "    A : Inst0.count : INT;\n    a : Inst0.setpoint : DINT;",
                "test.st:14:5: error: 'a' is already the name of a program instance or an "
                "access path"}),
    [](const auto& c) { return c.param.name; });

} // namespace
} // namespace eposp::compiler::test
