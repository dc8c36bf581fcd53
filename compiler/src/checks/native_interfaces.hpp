#pragma once

// What a native POU's interface may hold (docs/runtime.md, "Native functions", "Native function
// blocks"): the checks refuse the rest (E0419), code generation passes what is left.

#include "eposp/compiler/sema/type.hpp"

#include <optional>

namespace eposp::compiler::checks {

/// How a native function takes a parameter.
enum class NativeParameterKind {
    Value,  ///< an elementary value (an enumeration, a subrange), by value
    String, ///< a STRING or WSTRING, its address
    Any,    ///< ANY: the value's address, then its type's descriptor
    Array,  ///< VAR_IN_OUT ARRAY[*]: its reference's address, then the element's descriptor
};

/// How a native function takes `field` (a VAR_INPUT or VAR_IN_OUT); nullopt when it cannot.
std::optional<NativeParameterKind> native_parameter_kind(const sema::Field& field);
/// What an ANY input and an ARRAY[*]'s element may be: an elementary value or a string.
bool is_native_any_value(const sema::Type& type);
/// Whether a native function can return a `type`: an elementary value.
bool is_native_result(const sema::Type& type);
/// Whether a native block can have the variable `field`: elementary, or a VAR_IN_OUT.
bool is_native_block_variable(const sema::Field& field);

} // namespace eposp::compiler::checks
