#include "opcode_table.hpp"

#include <stdexcept>

namespace eposp::compiler::codegen {

OpcodeTable::OpcodeTable() {
    for (std::uint16_t i = 0; i < vm::kOpcodeCount; ++i) {
        const auto op = static_cast<vm::Opcode>(i);
        by_name_.emplace(std::string(vm::opcode_info(op).name), op);
    }
}

vm::Opcode OpcodeTable::get(std::string_view family, std::string_view suffix) const {
    const auto it = by_name_.find(std::string(family) + std::string(suffix));
    if (it == by_name_.end()) {
        throw std::logic_error("no opcode " + std::string(family) + std::string(suffix));
    }
    return it->second;
}

bool OpcodeTable::has(std::string_view family, std::string_view suffix) const {
    return by_name_.contains(std::string(family) + std::string(suffix));
}

std::string_view width_suffix(vm::Scalar scalar) {
    switch (vm::scalar_size(scalar)) {
    case 1:
        return "8";
    case 2:
        return "16";
    case 4:
        return "32";
    default:
        return "64";
    }
}

std::string_view type_suffix(vm::Scalar scalar) {
    using S = vm::Scalar;
    switch (scalar) {
    case S::Bool:
        return "Bool";
    case S::I8:
        return "I8";
    case S::I16:
        return "I16";
    case S::I32:
        return "I32";
    case S::I64:
        return "I64";
    case S::U8:
        return "U8";
    case S::U16:
        return "U16";
    case S::U32:
        return "U32";
    case S::U64:
    case S::Ptr:
        return "U64";
    case S::F32:
        return "F32";
    case S::F64:
        return "F64";
    }
    return "U64";
}

} // namespace eposp::compiler::codegen
