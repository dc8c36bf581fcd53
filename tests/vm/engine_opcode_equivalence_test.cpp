// Every instruction on plain operands, run by compiled code and by the interpreter (the
// reference) on the same edge values: integer limits, shift counts around the width, reals
// with halves, infinities and NaN, pointers to NULL, inside and outside memory. Both engines
// must end in the same state with the same fault, the same branch taken and the same bytes.
// Operands are read from the frame and the out area and written to the instance, so three of
// the four bases are exercised; the compiled ST programs of the compiler tests cover the rest.
// The instruction's first operand was just stored by the instruction before it, as in a chain
// of dependent instructions.

#include "vm_harness.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace eposp::vm::test {
namespace {

constexpr std::uint32_t kX = 0;       // 16 bytes: x, then bytes that pair with it
constexpr std::uint32_t kY = 16;      // 16 bytes: y (a subrange's bounds, a pair)
constexpr std::uint32_t kResult = 32; // written by the instruction, starting as x
constexpr std::uint32_t kTaken = 48;  // set where a branch is taken
constexpr std::uint32_t kCompared = 56;

std::vector<std::uint64_t> edge_values() {
    std::vector<std::uint64_t> values{0,
                                      1,
                                      2,
                                      7,
                                      8,
                                      16,
                                      31,
                                      32,
                                      33,
                                      63,
                                      64,
                                      100,
                                      0x7F,
                                      0x80,
                                      0xFF,
                                      0x7FFF,
                                      0x8000,
                                      0xFFFF,
                                      0x7FFFFFFF,
                                      0x80000000,
                                      0xFFFFFFFF,
                                      0x7FFFFFFFFFFFFFFF,
                                      0x8000000000000000,
                                      ~std::uint64_t{0},
                                      ~std::uint64_t{1},
                                      ~std::uint64_t{6}};
    for (double real :
         {2.5, -2.5, 0.49999999999999994, 1e300, -1e19, std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::quiet_NaN()}) {
        values.push_back(bits(real));
    }
    for (float real : {2.5F, -3.5F, 1e20F, std::numeric_limits<float>::quiet_NaN()}) {
        values.push_back(bits(real) | std::uint64_t{bits(-0.5F)} << 32);
    }
    return values;
}

/// Only fields a test can fill without a context: data operands, immediates and one target.
bool plain(const OpcodeInfo& info) {
    if (info.aux == Aux::Array) {
        return false;
    }
    for (const FieldSpec& field : {info.a, info.b, info.c}) {
        switch (field.field) {
        case Field::None:
        case Field::Read:
        case Field::Write:
        case Field::Imm:
        case Field::Target:
            break;
        default:
            return false;
        }
    }
    return true;
}

struct Outcome {
    RunState state = RunState::Idle;
    Trap trap = Trap::DivisionByZero;
    std::vector<std::uint8_t> bytes;

    bool operator==(const Outcome&) const = default;
};

/// The instruction `op` in Main, its reads from the frame (x) and the out area (y), its write
/// to the instance, a taken branch setting kTaken; linked for one engine.
class OneInstruction {
public:
    OneInstruction(Opcode op, std::uint32_t immediate, std::int16_t step, Engine engine) {
        const OpcodeInfo& info = opcode_info(op);
        Builder& b = harness_.builder;
        for (std::uint32_t at = 0; at < 16; at += 8) {
            b.emit(Opcode::Mov64, Operand::out(at), self(kY + at));
            b.emit(Opcode::Mov64, Operand::local(at), self(kX + at));
        }
        // x stored once more at the width the instruction reads it, so that compiled code
        // takes it from the register the store left it in.
        const FieldSpec first_read = info.a.field == Field::Read   ? info.a
                                     : info.b.field == Field::Read ? info.b
                                                                   : info.c;
        if (first_read.field == Field::Read && (first_read.size == 4 || first_read.size == 8)) {
            b.emit(first_read.size == 4 ? Opcode::Mov32 : Opcode::Mov64, Operand::local(0),
                   self(kX));
        }
        const Label taken = b.label();
        Operand fields[3];
        bool branches = false;
        int reads = 0;
        const FieldSpec specs[] = {info.a, info.b, info.c};
        for (int f = 0; f < 3; ++f) {
            switch (specs[f].field) {
            case Field::Write:
                fields[f] = self(kResult);
                break;
            case Field::Read:
                fields[f] = reads++ == 0 ? Operand::local(0) : Operand::out(0);
                break;
            case Field::Imm:
                fields[f] = Operand::imm(f == 1 ? immediate : immediate ^ 0x80000001U);
                break;
            case Field::Target:
                branches = true;
                break;
            default:
                break;
            }
        }
        const auto aux = static_cast<std::uint16_t>(step);
        if (branches) {
            // jump() takes the fields other than the target, in their order.
            std::vector<Operand> others;
            for (int f = 0; f < 3; ++f) {
                if (specs[f].field != Field::Target) {
                    others.push_back(fields[f]);
                }
            }
            b.jump(op, taken, others[0], others[1], info.aux == Aux::Step ? aux : 0);
        } else {
            b.emit(op, fields[0], fields[1], fields[2], info.aux == Aux::Step ? aux : 0);
        }
        b.emit(Opcode::Ret);
        b.bind(taken);
        b.emit(Opcode::Ldi8, self(kTaken), imm(1));
        b.emit(Opcode::Ret);
        harness_.end_main(64, 64);
        harness_.builder.task(Task{"T",
                                   TaskKind::Cyclic,
                                   1'000'000,
                                   0,
                                   0,
                                   4096,
                                   {TaskEntry{harness_.main, harness_.instance}}});
        auto image = harness_.builder.finish();
        if (!image) {
            ADD_FAILURE() << image.error();
            return;
        }
        auto linked = link(std::move(*image), harness_.natives, engine);
        if (!linked) {
            ADD_FAILURE() << linked.error();
            return;
        }
        program_.emplace(std::move(*linked));
        machine_.emplace(*program_);
    }

    bool ready() const { return machine_.has_value(); }
    bool compiled() const { return program_->engine() == Engine::Compiled; }

    /// `whole_memory`: compare all of it, not only Main's instance (a store through a pointer).
    Outcome run(std::uint64_t x, std::uint64_t y, bool whole_memory) {
        std::uint8_t* instance = machine_->memory().data() + harness_.instance;
        const std::uint64_t values[] = {x, x ^ y, y, y ^ 0x5555555555555555U, x, 0, 0};
        std::memcpy(instance, values, sizeof values);
        Outcome outcome;
        outcome.state = machine_->run_cycle(0);
        outcome.trap = machine_->task(0).fault.trap;
        if (whole_memory) {
            outcome.bytes.assign(machine_->memory().begin(), machine_->memory().end());
        } else {
            outcome.bytes.assign(instance, instance + kCompared);
        }
        return outcome;
    }

private:
    Harness harness_;
    std::optional<Program> program_;
    std::optional<Machine> machine_;
};

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
            OneInstruction reference(op, immediate, step, Engine::Interpreter);
            OneInstruction compiled(op, immediate, step, Engine::Compiled);
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

std::vector<std::uint16_t> plain_opcodes() {
    std::vector<std::uint16_t> opcodes;
    for (std::uint16_t op = 0; op < kOpcodeCount; ++op) {
        if (plain(opcode_info(static_cast<Opcode>(op))) && static_cast<Opcode>(op) != Opcode::Ret) {
            opcodes.push_back(op);
        }
    }
    return opcodes;
}

INSTANTIATE_TEST_SUITE_P(PlainOperands, EngineOpcodes, ::testing::ValuesIn(plain_opcodes()),
                         [](const ::testing::TestParamInfo<std::uint16_t>& op) {
                             return std::string(opcode_info(static_cast<Opcode>(op.param)).name);
                         });

} // namespace
} // namespace eposp::vm::test
