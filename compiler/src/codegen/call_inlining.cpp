#include "call_inlining.hpp"

#include <algorithm>
#include <numeric>
#include <optional>

namespace eposp::compiler::codegen {
namespace {

using vm::Base;
using vm::Field;
using vm::Opcode;
using vm::Operand;

/// Bodies up to this many instructions are copied: the standard FBs and small user POUs, whose
/// call and return cost about as much as the body; a larger body hides the call's cost.
constexpr std::uint32_t kMaxInlinedLength = 24;

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
        return true;
    default:
        return false;
    }
}

bool is_call(Opcode op) {
    return op == Opcode::Call || op == Opcode::CallFb || op == Opcode::CallFbP;
}

/// The POU `call` enters, when its body may replace the call: a short leaf (no calls of its
/// own, so nothing else expects its frame where a call would have put it), entered with an
/// instance the caller addresses directly.
std::optional<std::uint32_t> inlinable_callee(const vm::Image& image, const vm::Instruction& call) {
    std::uint32_t callee = 0;
    if (call.opcode == Opcode::Call) {
        callee = call.a;
    } else if (call.opcode == Opcode::CallFb && Operand{call.a}.base() != Base::Out) {
        callee = call.b;
    } else {
        return std::nullopt;
    }
    const vm::Pou& pou = image.pous[callee];
    const std::uint32_t length = pou.code_end - pou.code_begin;
    const auto body = image.code.begin() + pou.code_begin;
    if (length < 2 || length > kMaxInlinedLength ||
        std::any_of(body, body + length,
                    [](const vm::Instruction& ins) { return is_call(ins.opcode); })) {
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

template <typename Retarget>
void retarget(vm::Instruction& ins, const Retarget& to) {
    const vm::OpcodeInfo& info = vm::opcode_info(ins.opcode);
    std::uint32_t* fields[3] = {&ins.a, &ins.b, &ins.c};
    const vm::FieldSpec* specs[3] = {&info.a, &info.b, &info.c};
    for (int f = 0; f < 3; ++f) {
        if (specs[f]->field == Field::Target) {
            *fields[f] = to(*fields[f]);
        }
    }
}

/// The body of `callee` as it runs in place of `call` starting at instruction `start`: each
/// Ret a jump past the copy, the last one dropped. Empty when an operand cannot be moved.
std::vector<vm::Instruction> inlined_body(const vm::Image& image, std::uint32_t callee,
                                          const vm::Instruction& call, std::uint32_t start) {
    const vm::Pou& body = image.pous[callee];
    const Operand instance = call.opcode == Opcode::CallFb ? Operand{call.a} : Operand::self(0);
    const bool ends_in_ret = image.code[body.code_end - 1].opcode == Opcode::Ret;
    const std::uint32_t length = body.code_end - body.code_begin - (ends_in_ret ? 1 : 0);
    const std::uint32_t after = start + length;
    std::vector<vm::Instruction> copy;
    for (std::uint32_t i = body.code_begin; i < body.code_begin + length; ++i) {
        vm::Instruction ins = image.code[i];
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

/// POU indices in code order, if their bodies tile the code without gaps.
std::optional<std::vector<std::uint32_t>> pous_in_code_order(const vm::Image& image) {
    std::vector<std::uint32_t> order(image.pous.size());
    std::iota(order.begin(), order.end(), 0U);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return image.pous[a].code_begin < image.pous[b].code_begin;
    });
    std::uint32_t next = 0;
    for (const std::uint32_t p : order) {
        if (image.pous[p].code_begin != next) {
            return std::nullopt;
        }
        next = image.pous[p].code_end;
    }
    return next == image.code.size() ? std::optional(order) : std::nullopt;
}

} // namespace

void inline_leaf_calls(vm::Image& image) {
    const auto order = pous_in_code_order(image);
    if (!order) {
        return;
    }
    const vm::Image original = image;
    std::vector<vm::Instruction> code;
    for (const std::uint32_t p : *order) {
        const vm::Pou& old = original.pous[p];
        vm::Pou& pou = image.pous[p];
        // moved[i - old.code_begin]: where old instruction i (or the copy replacing it) starts.
        std::vector<std::uint32_t> moved(old.code_end - old.code_begin + 1);
        std::vector<std::size_t> own_jumps;
        const auto begin = static_cast<std::uint32_t>(code.size());
        for (std::uint32_t i = old.code_begin; i < old.code_end; ++i) {
            const auto here = static_cast<std::uint32_t>(code.size());
            moved[i - old.code_begin] = here;
            const vm::Instruction& ins = original.code[i];
            if (const auto callee = inlinable_callee(original, ins)) {
                auto body = inlined_body(original, *callee, ins, here);
                if (!body.empty()) {
                    const vm::Pou& inlined = original.pous[*callee];
                    pou.out_size = std::max(pou.out_size, inlined.frame_size + inlined.out_size);
                    pou.inlined.push_back(
                        {here, here + static_cast<std::uint32_t>(body.size()), *callee});
                    code.insert(code.end(), body.begin(), body.end());
                    continue;
                }
            }
            own_jumps.push_back(code.size());
            code.push_back(ins);
        }
        moved.back() = static_cast<std::uint32_t>(code.size());
        for (const std::size_t at : own_jumps) {
            retarget(code[at], [&](std::uint32_t target) { return moved[target - old.code_begin]; });
        }
        for (vm::LineEntry& line : pou.lines) {
            line.instruction = moved[line.instruction - old.code_begin];
        }
        pou.code_begin = begin;
        pou.code_end = static_cast<std::uint32_t>(code.size());
    }
    image.code = std::move(code);
}

} // namespace eposp::compiler::codegen
