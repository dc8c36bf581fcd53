#include "eposp/vm/opcodes.hpp"

#include "eposp/vm/instruction.hpp"

#include <array>

namespace eposp::vm {
namespace {

#define EPOSP_VM_INFO_ROW(name, family, T1, T2, aux, a, b, c) OpcodeInfo{#name, aux, a, b, c},
constexpr std::array<OpcodeInfo, kOpcodeCount> kInfo{{EPOSP_VM_OPCODES(EPOSP_VM_INFO_ROW)}};
#undef EPOSP_VM_INFO_ROW

} // namespace

const OpcodeInfo& opcode_info(Opcode op) {
    return kInfo[static_cast<std::size_t>(op)];
}

std::optional<std::uint32_t> branch_target(const Instruction& ins) {
    const OpcodeInfo& info = opcode_info(ins.opcode);
    if (info.a.field == Field::Target) {
        return ins.a;
    }
    if (info.b.field == Field::Target) {
        return ins.b;
    }
    if (info.c.field == Field::Target) {
        return ins.c;
    }
    return std::nullopt;
}

} // namespace eposp::vm
