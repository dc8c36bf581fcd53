#pragma once

// Instructions on plain operands, run by compiled code and by the interpreter (the reference) on
// the same edge values, to compare the two engines' end states: the frame's x (local 0) and the
// out area's y (out 0) are copied from Main's instance, the instructions read them and write to
// the instance, and a taken branch sets a flag there. Operands come from three of the four
// bases; the compiled ST programs of the compiler tests cover the rest.

#include "vm_harness.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace eposp::vm::test {

inline constexpr std::uint32_t kX = 0;       // 16 bytes: x, then bytes that pair with it
inline constexpr std::uint32_t kY = 16;      // 16 bytes: y (a subrange's bounds, a pair)
inline constexpr std::uint32_t kResult = 32; // written by the instruction, starting as x
inline constexpr std::uint32_t kTaken = 48;  // set where a branch is taken
inline constexpr std::uint32_t kCompared = 56;

/// Integer limits, shift counts around the width, reals with halves, infinities and NaN.
inline std::vector<std::uint64_t> edge_values() {
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
inline bool plain(const OpcodeInfo& info) {
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

/// The instruction's first read field (Field::None if it reads nothing).
inline FieldSpec first_read(const OpcodeInfo& info) {
    for (const FieldSpec& field : {info.a, info.b, info.c}) {
        if (field.field == Field::Read) {
            return field;
        }
    }
    return FieldSpec{};
}

/// The width of what the instruction writes (0 if nothing).
inline int written_bytes(const OpcodeInfo& info) {
    for (const FieldSpec& field : {info.a, info.b, info.c}) {
        if (field.field == Field::Write) {
            return field.size;
        }
    }
    return 0;
}

struct Outcome {
    RunState state = RunState::Idle;
    Trap trap = Trap::DivisionByZero;
    std::vector<std::uint8_t> bytes;

    bool operator==(const Outcome&) const = default;
};

inline void PrintTo(const Outcome& outcome, std::ostream* out) {
    *out << "state " << static_cast<int>(outcome.state) << ", trap "
         << static_cast<int>(outcome.trap) << ", bytes" << std::hex;
    for (std::size_t i = 0; i < outcome.bytes.size() && i < kCompared; ++i) {
        *out << (i % 8 == 0 ? "  " : " ") << static_cast<int>(outcome.bytes[i]);
    }
    *out << std::dec;
}

/// Emits `op` with its first read from x, its second from y, its write to `write_to`, an
/// immediate, the step of a FOR, and `taken` as its target.
inline void emit_plain(Builder& b, Opcode op, Operand write_to, std::uint32_t immediate,
                       std::int16_t step, Label taken) {
    const OpcodeInfo& info = opcode_info(op);
    Operand fields[3];
    bool branches = false;
    int reads = 0;
    const FieldSpec specs[] = {info.a, info.b, info.c};
    for (int f = 0; f < 3; ++f) {
        switch (specs[f].field) {
        case Field::Write:
            fields[f] = write_to;
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
}

/// Main copies x and y from its instance into the frame and the out area, runs the body that
/// `emit_body` emits (given the label a taken branch goes to), and returns; linked for one
/// engine.
class EngineProgram {
public:
    EngineProgram(const std::function<void(Builder&, Label taken)>& emit_body, Engine engine) {
        Builder& b = harness_.builder;
        for (std::uint32_t at = 0; at < 16; at += 8) {
            b.emit(Opcode::Mov64, Operand::out(at), self(kY + at));
            b.emit(Opcode::Mov64, Operand::local(at), self(kX + at));
        }
        const Label taken = b.label();
        emit_body(b, taken);
        b.emit(Opcode::Ret);
        b.bind(taken);
        b.emit(Opcode::Ldi8, self(kTaken), imm(1));
        b.emit(Opcode::Ret);
        harness_.end_main(64, 64);
        harness_.builder.task(Task{.name = "T",
                                   .kind = TaskKind::Cyclic,
                                   .interval_ns = 1'000'000,
                                   .stack_size = 4096,
                                   .entries = {TaskEntry{harness_.main, harness_.instance}}});
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

    // The machine refers to the program: the whole stays where it was made.
    EngineProgram(const EngineProgram&) = delete;
    EngineProgram& operator=(const EngineProgram&) = delete;

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

/// Every opcode whose OpcodeInfo `keep` accepts: the parameters of a suite over opcodes.
inline std::vector<std::uint16_t> opcodes_where(const std::function<bool(Opcode)>& keep) {
    std::vector<std::uint16_t> opcodes;
    for (std::uint16_t op = 0; op < kOpcodeCount; ++op) {
        if (keep(static_cast<Opcode>(op))) {
            opcodes.push_back(op);
        }
    }
    return opcodes;
}

/// A test instance named after its opcode.
inline std::string opcode_name(const ::testing::TestParamInfo<std::uint16_t>& op) {
    return std::string(opcode_info(static_cast<Opcode>(op.param)).name);
}

} // namespace eposp::vm::test
