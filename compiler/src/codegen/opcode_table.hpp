#pragma once

#include "eposp/vm/opcodes.hpp"
#include "eposp/vm/scalar.hpp"

#include <string>
#include <string_view>
#include <unordered_map>

namespace eposp::compiler::codegen {

/// Finds opcodes by family and type suffix (`Add` + `32`, `Lt` + `I16`, `Cvt` + `I16I32`),
/// from the names in vm/opcodes.hpp, so code generation never depends on the order of the
/// opcode list.
class OpcodeTable {
public:
    OpcodeTable();
    /// The opcode `family` + `suffix`; a programming error if there is none.
    vm::Opcode get(std::string_view family, std::string_view suffix) const;
    bool has(std::string_view family, std::string_view suffix) const;

private:
    std::unordered_map<std::string, vm::Opcode> by_name_;
};

/// `8`, `16`, `32`, `64`: the sign-agnostic suffix of a scalar.
std::string_view width_suffix(vm::Scalar scalar);
/// `Bool`, `I8` … `U64`, `F32`, `F64` (a pointer is `U64`).
std::string_view type_suffix(vm::Scalar scalar);

} // namespace eposp::compiler::codegen
