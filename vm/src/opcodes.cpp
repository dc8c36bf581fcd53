#include "eposp/vm/opcodes.hpp"

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

} // namespace eposp::vm
