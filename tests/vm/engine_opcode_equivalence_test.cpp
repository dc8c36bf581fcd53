// Every instruction on plain operands, run by compiled code and by the interpreter (the
// reference) on the same edge values: integer limits, shift counts around the width, reals
// with halves, infinities and NaN, pointers to NULL, inside and outside memory. Both engines
// must end in the same state with the same fault, the same branch taken and the same bytes.
// Operands are read from the frame and the out area and written to the instance, so three of
// the four bases are exercised; the compiled ST programs of the compiler tests cover the rest.
// The instruction's first operand was just stored by the instruction before it, as in a chain
// of dependent instructions.

#include "engine_equivalence.hpp"

namespace eposp::vm::test {
namespace {

/// The instruction `op` in Main, x stored once more just before it at the width it reads x.
EngineProgram one_instruction(Opcode op, std::uint32_t immediate, std::int16_t step,
                              Engine engine) {
    return EngineProgram(
        [&](Builder& b, Label taken) {
            // So that compiled code takes x from the register the store left it in.
            const FieldSpec read = first_read(opcode_info(op));
            if (read.size == 4 || read.size == 8) {
                b.emit(read.size == 4 ? Opcode::Mov32 : Opcode::Mov64, Operand::local(0), self(kX));
            }
            emit_plain(b, op, self(kResult), immediate, step, taken);
        },
        engine);
}

class EngineOpcodes : public ::testing::TestWithParam<std::uint16_t> {};

TEST_P(EngineOpcodes, CompiledCodeGivesTheInterpretersResult) {
    const auto op = static_cast<Opcode>(GetParam());
    const OpcodeInfo& info = opcode_info(op);
    const auto values = edge_values();
    const std::vector<std::int16_t> steps =
        info.aux == Aux::Step ? std::vector<std::int16_t>{1, -1, 3} : std::vector<std::int16_t>{0};
    const bool has_immediate =
        info.a.field == Field::Imm || info.b.field == Field::Imm || info.c.field == Field::Imm;
    const std::vector<std::uint32_t> immediates =
        has_immediate ? std::vector<std::uint32_t>{0, 5, 0xFFFFFFF0U}
                      : std::vector<std::uint32_t>{0};
    const bool through_pointer = info.name.starts_with("Stp");
    for (std::int16_t step : steps) {
        for (std::uint32_t immediate : immediates) {
            EngineProgram reference = one_instruction(op, immediate, step, Engine::Interpreter);
            EngineProgram compiled = one_instruction(op, immediate, step, Engine::Compiled);
            ASSERT_TRUE(reference.ready() && compiled.ready());
            if (!compiled.compiled()) {
                GTEST_SKIP() << "this build or machine has no translator to machine code";
            }
            for (std::uint64_t x : values) {
                for (std::uint64_t y : values) {
                    ASSERT_EQ(compiled.run(x, y, through_pointer),
                              reference.run(x, y, through_pointer))
                        << info.name << " x=" << std::hex << x << " y=" << y << " imm=" << immediate
                        << std::dec << " step=" << step;
                }
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(PlainOperands, EngineOpcodes,
                         ::testing::ValuesIn(opcodes_where([](Opcode op) {
                             return plain(opcode_info(op)) && op != Opcode::Ret;
                         })),
                         opcode_name);

} // namespace
} // namespace eposp::vm::test
