// The example and benchmark ST programs that the reference evaluator supports, run on it and on
// the engine under test (StProgram: the compiled engine, or the interpreter with
// EPOSP_VM_ENGINE=interpreter): every elementary variable must agree after each scan.

#include "codegen_harness.hpp"
#include "eposp/reference/reference_program.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace eposp::reference {
namespace {

std::string read(const std::string& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

/// Every elementary (or STRING) variable below `path` of type `type` in the image.
void leaves(const vm::Image& image, std::uint32_t type, const std::string& path,
            std::vector<std::pair<std::string, const vm::TypeDescriptor*>>& out) {
    const vm::TypeDescriptor& descriptor = image.types[type];
    switch (descriptor.kind) {
    case vm::TypeKind::Elementary:
    case vm::TypeKind::String:
        out.emplace_back(path, &descriptor);
        return;
    case vm::TypeKind::Array:
        for (std::uint32_t i = 0; i < descriptor.count; ++i) {
            leaves(image, descriptor.element,
                   path + "[" + std::to_string(descriptor.lower + static_cast<std::int32_t>(i)) +
                       "]",
                   out);
        }
        return;
    case vm::TypeKind::Struct:
        for (const vm::TypeField& field : descriptor.fields) {
            leaves(image, field.type, path + "." + field.name, out);
        }
        return;
    }
}

std::uint64_t engine_bits(const compiler::test::StProgram& program, const std::string& path,
                          std::uint32_t size) {
    switch (size) {
    case 1:
        return program.get<std::uint8_t>(path);
    case 2:
        return program.get<std::uint16_t>(path);
    case 4:
        return program.get<std::uint32_t>(path);
    default:
        return program.get<std::uint64_t>(path);
    }
}

class ExampleProgram : public testing::TestWithParam<std::string> {};

TEST_P(ExampleProgram, AgreesWithTheEngineOnEveryVariable) {
    const std::string source = read(std::string(EPOSP_SOURCE_DIR) + "/" + GetParam());
    ASSERT_FALSE(source.empty()) << GetParam();
    ReferenceProgram reference({{"program.st", source}});
    if (!reference.ok()) {
        ASSERT_NE(reference.errors().find("not supported by the reference evaluator"),
                  std::string::npos)
            << reference.errors();
        GTEST_SKIP() << reference.errors();
    }
    compiler::test::StProgram engine({{"program.st", source}});
    ASSERT_TRUE(engine.ok()) << engine.errors();
    std::vector<std::pair<std::string, const vm::TypeDescriptor*>> variables;
    for (const vm::Symbol& symbol : engine.image().symbols) {
        leaves(engine.image(), symbol.type, symbol.path, variables);
    }
    std::size_t compared = 0;
    // 20 scans 50 ms apart: long enough for the examples' timers to run out.
    constexpr std::int64_t kStepNs = 50'000'000;
    for (int scan = 0; scan < 20; ++scan) {
        const bool engine_ran = engine.scans(1, kStepNs);
        const bool reference_ran = reference.scans(1, kStepNs);
        if (!reference_ran && reference.fault().starts_with("not supported")) {
            GTEST_SKIP() << reference.fault();
        }
        ASSERT_EQ(engine_ran, reference_ran) << "scan " << scan << ": engine " << engine.fault()
                                             << ", reference " << reference.fault();
        if (!engine_ran) {
            break;
        }
        for (const auto& [path, type] : variables) {
            if (type->kind == vm::TypeKind::String) {
                if (const auto text = reference.string(path)) {
                    ASSERT_EQ(engine.get_string(path), *text) << path << " after scan " << scan;
                    ++compared;
                }
            } else if (const auto bits = reference.bits(path)) {
                ASSERT_EQ(engine_bits(engine, path, type->size), *bits)
                    << path << " after scan " << scan;
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Examples, ExampleProgram,
    testing::Values("examples/plc-basics/blinker.st", "examples/plc-basics/connections.st",
                    "tests/compiler/inputs/bubble_sort.st", "tests/compiler/inputs/conveyor_fsm.st",
                    "tests/compiler/inputs/crc32.st", "tests/compiler/inputs/fb_channels.st",
                    "tests/compiler/inputs/pid_plant.st", "tests/compiler/inputs/sieve.st",
                    "tests/compiler/inputs/strings.st", "tests/compiler/inputs/program_calls.st"),
    [](const testing::TestParamInfo<std::string>& param) {
        std::string name = param.param.substr(param.param.find_last_of('/') + 1);
        name = name.substr(0, name.find('.'));
        std::erase(name, '-');
        std::erase(name, '_');
        return name;
    });

} // namespace
} // namespace eposp::reference
