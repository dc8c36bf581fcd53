#pragma once

#include "eposp/compiler/sema/type.hpp"
#include "eposp/vm/instruction.hpp"

#include <cstdint>

namespace eposp::compiler::codegen {

/// Where a value lives, as the VM can reach it: directly by an operand, as an element of an
/// array operand indexed by a DINT operand (Ldx/Stx), or through a pointer plus an offset
/// (Ldp/Stp: array elements that are not scalars, VAR_IN_OUT, `ref^`, FB instances in arrays).
struct Place {
    enum class Kind { Direct, Element, Indirect };
    Kind kind = Kind::Direct;
    const sema::Type* type = nullptr;
    vm::Operand operand{};    ///< Direct: the value; Element: the array; Indirect: the pointer
    vm::Operand index{};      ///< Element: the DINT index
    std::uint16_t array = 0;  ///< Element: the array descriptor
    std::uint32_t offset = 0; ///< Indirect: bytes past the pointer
    bool writable = true;     ///< false for constants and inputs of the running function

    static Place direct(const sema::Type& type, vm::Operand operand, bool writable = true) {
        return {.kind = Kind::Direct, .type = &type, .operand = operand, .writable = writable};
    }
};

/// `operand` moved `delta` bytes on in the same area.
inline vm::Operand shifted(vm::Operand operand, std::uint32_t delta) {
    return vm::Operand::at(operand.base(), operand.offset() + delta);
}

} // namespace eposp::compiler::codegen
