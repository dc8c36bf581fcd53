// What compile() puts into the image besides code: tasks, symbols, retain ranges and I/O
// bindings; and that it never crashes, whatever is taken out of a real program.
#include "codegen_harness.hpp"
#include "eposp/compiler/compiler.hpp"
#include "eposp/vm/verifier.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace eposp::compiler::test {
namespace {

std::optional<vm::Image> compile_text(const std::string& text, std::string* rendered = nullptr) {
    SourceManager sources;
    const FileId file = sources.add("test.st", text);
    Diagnostics diagnostics;
    auto image = compile(sources, {&file, 1}, diagnostics);
    if (rendered != nullptr) {
        *rendered = render(diagnostics, sources);
    }
    return image;
}

TEST(Image, TasksRetainBindingsAndSymbols) {
    std::string errors;
    const auto image = compile_text(R"(
PROGRAM Prog
  VAR_EXTERNAL level : INT; END_VAR
  VAR RETAIN kept : DINT; END_VAR
  VAR sensor AT %IW4 : INT; lamp AT %QX1.3 : BOOL; n : INT; END_VAR
  n := sensor + level;
  lamp := kept > 0;
END_PROGRAM
CONFIGURATION Cfg
  VAR_GLOBAL RETAIN level : INT; END_VAR
  RESOURCE R ON PLC
    TASK Slow(INTERVAL := T#20ms, PRIORITY := 3);
    PROGRAM P WITH Slow : Prog;
  END_RESOURCE
END_CONFIGURATION
)",
                                    &errors);
    ASSERT_TRUE(image) << errors;
    ASSERT_EQ(image->tasks.size(), 1u);
    EXPECT_EQ(image->tasks[0].name, "Slow");
    EXPECT_EQ(image->tasks[0].interval_ns, 20'000'000u);
    EXPECT_EQ(image->tasks[0].priority, 3u);
    ASSERT_EQ(image->tasks[0].entries.size(), 1u);
    EXPECT_EQ(image->retain.size(), 2u);
    ASSERT_EQ(image->bindings.size(), 2u);
    EXPECT_EQ(image->bindings[0].area, vm::IoArea::Input);
    EXPECT_EQ(image->bindings[0].byte_address, 8u);
    EXPECT_EQ(image->bindings[0].type, vm::Scalar::I16);
    EXPECT_EQ(image->bindings[1].area, vm::IoArea::Output);
    EXPECT_EQ(image->bindings[1].byte_address, 1u);
    EXPECT_EQ(image->bindings[1].bit, 3);
    std::vector<std::string> paths;
    for (const auto& symbol : image->symbols) {
        paths.push_back(symbol.path);
    }
    EXPECT_EQ(paths, (std::vector<std::string>{"Cfg.level", "P"}));
    EXPECT_FALSE(image->pous.front().lines.empty());
}

TEST(Image, AddressesUsedInCodeAreBound) {
    std::string errors;
    const auto image = compile_text(R"(
PROGRAM Main
VAR n : WORD; END_VAR
n := %IW2 AND 16#00FF;
%QX0.1 := %IX0.0 AND NOT %IX0.0;
%MD4 := WORD_TO_DWORD(n);
END_PROGRAM
)",
                                    &errors);
    ASSERT_TRUE(image) << errors;
    ASSERT_EQ(image->bindings.size(), 4u);
    EXPECT_EQ(image->bindings[0].byte_address, 4u);
    EXPECT_EQ(image->bindings[0].type, vm::Scalar::U16);
    EXPECT_EQ(image->bindings[2].area, vm::IoArea::Input);
    EXPECT_EQ(image->bindings[3].area, vm::IoArea::Memory);
    EXPECT_EQ(image->bindings[3].byte_address, 16u);
    std::string refused;
    EXPECT_FALSE(compile_text("PROGRAM Main %IX0.0 := TRUE; END_PROGRAM", &refused));
    EXPECT_NE(refused.find("cannot be assigned"), std::string::npos) << refused;
}

TEST(Image, ProgramWithoutConfigurationGetsADefaultTask) {
    const auto image = compile_text("PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM");
    ASSERT_TRUE(image);
    ASSERT_EQ(image->tasks.size(), 1u);
    EXPECT_EQ(image->tasks[0].kind, vm::TaskKind::Cyclic);
    EXPECT_EQ(image->tasks[0].interval_ns, 10'000'000u);
    EXPECT_EQ(image->symbols.front().path, "Main");
}

// Every bench program with each line in turn left out: many broken programs, none may crash.
TEST(Robustness, BenchProgramsWithALineMissingNeverCrash) {
    for (const char* name :
         {"bubble_sort", "conveyor_fsm", "crc32", "pid_plant", "sieve", "strings"}) {
        std::ifstream file(std::string(EPOSP_SOURCE_DIR) + "/tests/compiler/inputs/" + name +
                           ".st");
        std::vector<std::string> lines;
        for (std::string line; std::getline(file, line);) {
            lines.push_back(line);
        }
        for (std::size_t skip = 0; skip < lines.size(); ++skip) {
            std::string text;
            for (std::size_t i = 0; i < lines.size(); ++i) {
                if (i != skip) {
                    text += lines[i] + "\n";
                }
            }
            if (const auto image = compile_text(text)) {
                const auto defect = vm::verify(*image);
                EXPECT_FALSE(defect)
                    << name << " without line " << skip + 1 << ": " << defect->message;
            }
        }
    }
}

} // namespace
} // namespace eposp::compiler::test
