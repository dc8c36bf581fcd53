#include "call_inlining.hpp"

#include "code_rewriter.hpp"

#include <algorithm>
#include <optional>

namespace eposp::compiler::lower {
namespace {

using vm::Base;
using vm::Field;
using vm::Opcode;
using vm::Operand;

/// Bodies up to this many instructions are copied: the standard FBs and small user POUs, whose
/// call and return cost about as much as the body; a larger body hides the call's cost.
constexpr std::uint32_t kMaxInlinedLength = 24;

// Every kind is listed (no default), so that a new kind of field cannot go unrelocated.
bool is_memory_operand(Field field) {
    switch (field) {
    case Field::Read:
    case Field::Write:
    case Field::ReadN:
    case Field::WriteN:
    case Field::ArrayRead:
    case Field::ArrayWrite:
    case Field::ArrayIndex:
    case Field::NativeArguments:
    case Field::Instance:
        return true;
    case Field::None:
    case Field::Imm:
    case Field::Size:
    case Field::Target:
    case Field::Pou:
    case Field::Import:
    case Field::JumpTable:
        return false;
    }
    return false;
}

/// Calls would need the callee's frame where a call puts it; a jump table belongs to one
/// instruction and cannot be shared by a copy.
bool keeps_body_in_place(Opcode op) {
    return op == Opcode::Call || op == Opcode::CallFb || op == Opcode::CallFbP ||
           jumps_through_table(op);
}

/// The POU `call` enters, when its body may replace the call: short, without calls or jump
/// tables, entered with an instance the caller addresses directly.
std::optional<std::uint32_t> inlinable_callee(const CodeBefore& before,
                                              const vm::Instruction& call) {
    std::uint32_t callee = 0;
    if (call.opcode == Opcode::Call) {
        callee = call.a;
    } else if (call.opcode == Opcode::CallFb && Operand{call.a}.base() != Base::Out) {
        callee = call.b;
    } else {
        return std::nullopt;
    }
    const vm::Pou& pou = before.pous[callee];
    const std::uint32_t length = pou.code_end - pou.code_begin;
    const auto body = before.code.begin() + pou.code_begin;
    if (length < 2 || length > kMaxInlinedLength ||
        std::any_of(body, body + length,
                    [](const vm::Instruction& ins) { return keeps_body_in_place(ins.opcode); })) {
        return std::nullopt;
    }
    return callee;
}

/// A callee operand as the caller sees it: the callee's frame is the caller's out area (where
/// the call would have put it), its out area follows that frame, its instance is `instance`.
std::optional<Operand> relocate(Operand operand, const vm::Pou& callee, Operand instance) {
    std::uint64_t offset = operand.offset();
    Base base = operand.base();
    switch (base) {
    case Base::Static:
        return operand;
    case Base::Frame:
        base = Base::Out;
        break;
    case Base::Out:
        offset += callee.frame_size;
        break;
    case Base::Self:
        base = instance.base();
        offset += instance.offset();
        break;
    }
    if (offset > vm::kOffsetMask) {
        return std::nullopt;
    }
    return Operand::at(base, static_cast<std::uint32_t>(offset));
}

/// The body of `callee` as it runs in place of `call` starting at instruction `start`: each
/// Ret a jump past the copy, the last one dropped. Empty when an operand cannot be moved.
std::vector<vm::Instruction> inlined_body(const CodeBefore& before, std::uint32_t callee,
                                          const vm::Instruction& call, std::uint32_t start) {
    const vm::Pou& body = before.pous[callee];
    const Operand instance = call.opcode == Opcode::CallFb ? Operand{call.a} : Operand::self(0);
    const bool ends_in_ret = before.code[body.code_end - 1].opcode == Opcode::Ret;
    const std::uint32_t length = body.code_end - body.code_begin - (ends_in_ret ? 1 : 0);
    const std::uint32_t after = start + length;
    std::vector<vm::Instruction> copy;
    for (std::uint32_t i = body.code_begin; i < body.code_begin + length; ++i) {
        vm::Instruction ins = before.code[i];
        if (ins.opcode == Opcode::Ret) {
            copy.push_back({Opcode::Jmp, 0, after, 0, 0});
            continue;
        }
        const vm::OpcodeInfo& info = vm::opcode_info(ins.opcode);
        std::uint32_t* fields[3] = {&ins.a, &ins.b, &ins.c};
        const vm::FieldSpec* specs[3] = {&info.a, &info.b, &info.c};
        for (int f = 0; f < 3; ++f) {
            if (is_memory_operand(specs[f]->field)) {
                const auto moved = relocate(Operand{*fields[f]}, body, instance);
                if (!moved) {
                    return {};
                }
                *fields[f] = moved->raw;
            }
        }
        retarget(ins, [&](std::uint32_t target) { return start + (target - body.code_begin); });
        copy.push_back(ins);
    }
    return copy;
}

} // namespace

void inline_leaf_calls(vm::Image& image) {
    rewrite_code(image, [](const CodeBefore& before, vm::Pou& pou, std::uint32_t i,
                           CodeSink& sink) {
        const vm::Instruction& ins = before.code[i];
        if (const auto callee = inlinable_callee(before, ins)) {
            const auto body = inlined_body(before, *callee, ins, sink.here());
            if (!body.empty()) {
                const vm::Pou& inlined = before.pous[*callee];
                pou.out_size = std::max(pou.out_size, inlined.frame_size + inlined.out_size);
                pou.inlined.push_back(
                    {sink.here(), sink.here() + static_cast<std::uint32_t>(body.size()), *callee});
                for (const vm::Instruction& copied : body) {
                    sink.place(copied);
                }
                return;
            }
        }
        sink.keep(ins);
    });
}

} // namespace eposp::compiler::lower
