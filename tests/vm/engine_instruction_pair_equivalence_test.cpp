// Pairs of dependent instructions on plain operands, run by compiled code and by the interpreter
// (the reference): the first writes x back at its own width, the second reads it at once, as in
// every chain of a compiled expression. Compiled code takes such a value from the register the
// store left it in, so the pair checks that the register holds exactly what a load of the
// stored bytes would give, whatever the second instruction does with it: extend it to 64 bits
// (a narrowing conversion followed by a widening one, issue 16 defect 1), convert it to a real,
// compare it, branch on it.

#include "engine_equivalence.hpp"

namespace eposp::vm::test {
namespace {

/// x and y values for pairs: fewer than for one instruction, as there are many pairs, but with
/// every upper half that a narrow store could leave behind.
std::vector<std::uint64_t> pair_values() {
    return {0,
            1,
            0x7F,
            0x80,
            0x8000,
            0x7FFFFFFF,
            0x80000000,
            0xFFFFFFFF,
            0x7FFFFFFFFFFFFFFF,
            0x8000000000000000,
            ~std::uint64_t{0},
            ~std::uint64_t{1},
            0xFFFFFFFF80000000,
            0x123456789ABCDEF0,
            bits(2.5),
            bits(-0.5F) | std::uint64_t{bits(3.5F)} << 32};
}

bool branches(const OpcodeInfo& info) {
    return info.a.field == Field::Target || info.b.field == Field::Target ||
           info.c.field == Field::Target;
}

/// Compiled code keeps a stored value in a register only at 4 and 8 bytes.
bool producer(const OpcodeInfo& info) {
    const int bytes = written_bytes(info);
    return plain(info) && !branches(info) && (bytes == 4 || bytes == 8);
}

class EnginePairs : public ::testing::TestWithParam<std::uint16_t> {};

TEST_P(EnginePairs, CompiledCodeGivesTheInterpretersResultForEveryDependentSecond) {
    const auto first = static_cast<Opcode>(GetParam());
    const int bytes = written_bytes(opcode_info(first));
    const auto values = pair_values();
    for (std::uint16_t code = 0; code < kOpcodeCount; ++code) {
        const auto second = static_cast<Opcode>(code);
        const OpcodeInfo& info = opcode_info(second);
        if (!plain(info) || second == Opcode::Ret || first_read(info).size != bytes) {
            continue;
        }
        const auto body = [&](Builder& b, Label taken) {
            emit_plain(b, first, Operand::local(0), 5, 1, taken);
            emit_plain(b, second, self(kResult), 5, 1, taken);
        };
        EngineProgram reference(body, Engine::Interpreter);
        EngineProgram compiled(body, Engine::Compiled);
        ASSERT_TRUE(reference.ready() && compiled.ready());
        if (!compiled.compiled()) {
            GTEST_SKIP() << "this build or machine has no translator to machine code";
        }
        const bool through_pointer = info.name.starts_with("Stp");
        for (std::uint64_t x : values) {
            for (std::uint64_t y : values) {
                ASSERT_EQ(compiled.run(x, y, through_pointer), reference.run(x, y, through_pointer))
                    << opcode_info(first).name << " then " << info.name << " x=" << std::hex << x
                    << " y=" << y;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(StoreThenLoad, EnginePairs,
                         ::testing::ValuesIn(opcodes_where([](Opcode op) {
                             return producer(opcode_info(op));
                         })),
                         opcode_name);

} // namespace
} // namespace eposp::vm::test
