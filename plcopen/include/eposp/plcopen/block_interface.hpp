#pragma once

#include "eposp/vm/native.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace eposp::plcopen {

/// The section a variable of a native block is declared in.
enum class Section { InOut, Input, Output, Var };

/// One variable of a native block: what the ST declaration says and what C++ reads.
struct BlockVariable {
    Section section;
    std::string_view name;
    std::string_view type; ///< the ST type: an elementary type, an enumeration, AXIS_REF
    vm::Scalar scalar;     ///< how C++ reads it (Ptr for VAR_IN_OUT)
};

/// A native function block described once: its ST declaration (for the library the compiler
/// reads) and its instance layout (for the VM) both come from this, so they cannot disagree.
/// The fields are in declaration order; a block's C++ body names them by their index.
struct BlockInterface {
    std::string_view name;
    std::vector<BlockVariable> variables;

    /// `FUNCTION_BLOCK name VAR_IN_OUT … END_FUNCTION_BLOCK`, without statements.
    std::string declaration() const;
    /// The scalars of the instance's fields, for vm::NativeRegistry::add_block.
    std::vector<vm::Scalar> fields() const;
};

} // namespace eposp::plcopen
