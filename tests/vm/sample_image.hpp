#pragma once

// A small but complete image (every table filled) for the format, verifier and disassembler
// tests: PROGRAM Main with a counter, an array, a function call, a jump table and a native
// import.

#include "eposp/vm/builder.hpp"

namespace eposp::vm::test {

inline Image sample_image() {
    Builder b;
    const auto dint =
        b.type(TypeDescriptor{"DINT", TypeKind::Elementary, Scalar::I32, 4, 0, 0, 0, {}});
    const auto lreal =
        b.type(TypeDescriptor{"LREAL", TypeKind::Elementary, Scalar::F64, 8, 0, 0, 0, {}});
    const auto array = b.type(
        TypeDescriptor{"ARRAY[1..4] OF DINT", TypeKind::Array, Scalar::Bool, 16, dint, 1, 4, {}});
    const auto main_type =
        b.type(TypeDescriptor{"Main",
                              TypeKind::Struct,
                              Scalar::Bool,
                              32,
                              0,
                              0,
                              0,
                              {{"counter", dint, 0}, {"values", array, 4}, {"r", lreal, 24}}});
    const auto main = b.declare_pou("Main", PouKind::Program, 32);
    const auto twice = b.declare_pou("Twice", PouKind::Function);
    const auto instance = b.allocate(32, 8);
    const auto input = b.allocate(2, 2);
    const NativeSignature sqrt_signature{true, Scalar::F64, {Scalar::F64}};
    const auto sqrt_import = b.import("SQRT", sqrt_signature);
    const auto values = b.array({1, 4, 4});

    b.begin_body(main);
    b.line(3);
    b.emit(Opcode::AddI32, Operand::self(0), Operand::self(0), Operand::imm(1));
    b.line(4);
    b.emit(Opcode::Mov32, Operand::out(0), Operand::self(0));
    b.emit(Opcode::Call, Operand::imm(twice));
    b.emit(Opcode::Stx32, Operand::self(4), Operand::self(0), Operand::out(4), values);
    b.line(5);
    b.emit(Opcode::CvtI32F64, Operand::out(8), Operand::self(0));
    b.emit(Opcode::CallNative, Operand::imm(sqrt_import), Operand::out(0));
    b.emit(Opcode::Mov64, Operand::self(24), Operand::out(0));
    auto done = b.label();
    b.jump(Opcode::JLtI32, done, Operand::self(0), Operand::self(0));
    b.jump(Opcode::JTab32, done, Operand::self(0), Operand::imm(b.jump_table(1, {done, done})));
    b.bind(done);
    b.emit(Opcode::Ret);
    b.end_body(0, 16);

    b.begin_body(twice);
    b.line(10);
    b.emit(Opcode::Add32, Operand::local(4), Operand::local(0), Operand::local(0));
    b.emit(Opcode::Ret);
    b.end_body(8);

    b.symbol("Inst0", main_type, instance);
    b.symbol("Inst0.counter", dint, instance);
    b.binding(IoBinding{IoArea::Input, Scalar::I16, 4, 0, input});
    b.retain(instance, 4);
    b.task(Task{.name = "MainTask",
                .kind = TaskKind::Cyclic,
                .interval_ns = 1'000'000,
                .priority = 1,
                .stack_size = 1024,
                .entries = {{main, instance}}});
    return std::move(*b.finish());
}

} // namespace eposp::vm::test
