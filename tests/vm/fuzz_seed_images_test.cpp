// The seed corpus of the program_image fuzz target (tests/fuzz/corpus/program_image) is made
// here with the Builder, so that it stays a set of valid images as the format evolves: each
// test fails when its committed file differs from what it builds, and rewrites the file when
// EPOSP_WRITE_FUZZ_SEEDS is set (then commit the changed files).

#include "eposp/vm/image_format.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"
#include "sample_image.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace eposp::vm::test {
namespace {

const std::filesystem::path kCorpus = EPOSP_PROGRAM_IMAGE_CORPUS;

/// PROGRAM Main: text := CONCAT(text, 'ab') ten times, then n := LEN(text) and p := FIND(text,
/// 'ba'): loops, string natives and their pointer arguments.
Image string_loop_image() {
    NativeRegistry natives;
    stdlib::register_standard_library(natives);
    Builder b;
    const auto main = b.declare_pou("Main", PouKind::Program, 16);
    const auto instance = b.allocate(16, 8);
    const auto text_bytes = stdlib::string_image(16, "");
    const auto text = b.allocate(static_cast<std::uint32_t>(text_bytes.size()), 2);
    b.initialise(text, text_bytes);
    const auto ab = b.constant(stdlib::string_image(2, "ab"), 2);
    const auto ba = b.constant(stdlib::string_image(2, "ba"), 2);
    const auto concat = b.import("CONCAT", natives.find("CONCAT")->signature);
    const auto len = b.import("LEN", natives.find("LEN")->signature);
    const auto find = b.import("FIND", natives.find("FIND")->signature);
    const auto one = b.constant(std::int32_t{1});
    const auto ten = b.constant(std::int32_t{10});
    const auto address = [&](std::uint32_t out, std::uint32_t string) {
        b.emit(Opcode::Addr, Operand::out(out), Operand::global(string), Operand::imm(4));
    };

    b.begin_body(main);
    b.line(1);
    b.emit(Opcode::Mov32, Operand::self(0), Operand::global(one));
    const auto body = b.label();
    b.bind(body);
    b.line(2);
    address(0, text);
    address(8, text);
    address(16, ab);
    b.emit(Opcode::CallNative, Operand::imm(concat), Operand::out(0));
    b.for_loop(Opcode::ForI32, body, Operand::self(0), Operand::global(ten), 1);
    b.line(3);
    address(8, text);
    b.emit(Opcode::CallNative, Operand::imm(len), Operand::out(0));
    b.emit(Opcode::Mov32, Operand::self(4), Operand::out(0));
    address(8, text);
    address(16, ba);
    b.emit(Opcode::CallNative, Operand::imm(find), Operand::out(0));
    b.emit(Opcode::Mov32, Operand::self(8), Operand::out(0));
    b.emit(Opcode::Ret);
    b.end_body(0, 24);

    b.task(Task{.name = "MainTask",
                .kind = TaskKind::Cyclic,
                .interval_ns = 10'000'000,
                .stack_size = 256,
                .entries = {{main, instance}}});
    return std::move(*b.finish());
}

void check_seed(const std::string& name, const Image& image) {
    const auto bytes = write_image(image);
    const auto path = kCorpus / name;
    if (std::getenv("EPOSP_WRITE_FUZZ_SEEDS") != nullptr) {
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()));
    }
    std::ifstream file(path, std::ios::binary);
    const std::vector<std::uint8_t> committed{std::istreambuf_iterator<char>(file), {}};
    EXPECT_EQ(committed, bytes) << path << " is stale: rerun with EPOSP_WRITE_FUZZ_SEEDS=1";
}

TEST(ProgramImageSeeds, SampleImageIsCurrent) {
    check_seed("sample.epx", sample_image());
}

TEST(ProgramImageSeeds, StringLoopImageIsCurrent) {
    check_seed("string_loop.epx", string_loop_image());
}

TEST(ProgramImageSeeds, StringLoopImageRunsToItsResult) {
    NativeRegistry natives;
    stdlib::register_standard_library(natives);
    auto program = link(string_loop_image(), natives);
    ASSERT_TRUE(program) << program.error();
    Machine machine(*program);
    ASSERT_EQ(machine.run_cycle(0), RunState::Finished) << machine.describe_fault(0);
    const auto instance = program->image().tasks[0].entries[0].instance;
    std::int32_t length = 0;
    std::int32_t position = 0;
    std::memcpy(&length, machine.memory().data() + instance + 4, 4);
    std::memcpy(&position, machine.memory().data() + instance + 8, 4);
    EXPECT_EQ(length, 16); // 20 characters cut at STRING[16]
    EXPECT_EQ(position, 2);
}

} // namespace
} // namespace eposp::vm::test
