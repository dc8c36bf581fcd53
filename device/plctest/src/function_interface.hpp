#pragma once

// A native FUNCTION described once: its ST declaration (for the library the compiler links) and
// its NativeSignature (for the registry) both come from this, so they cannot disagree.

#include "eposp/vm/native.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::plctest {

/// How an input reaches C++ (docs/runtime.md, "Native functions").
enum class Passed : std::uint8_t {
    Value,  ///< an elementary VAR_INPUT, by value
    String, ///< a STRING / WSTRING VAR_INPUT, by address
    Any,    ///< an ANY VAR_INPUT: address and type descriptor
    Array,  ///< a VAR_IN_OUT ARRAY[*]: reference and element descriptor
};

struct FunctionParameter {
    std::string name;
    std::string type; ///< as ST writes it: `DINT`, `STRING(255)`, `ANY`, `ARRAY[*] OF DINT`
    Passed passed = Passed::Value;
    vm::Scalar scalar = vm::Scalar::Bool; ///< Value only
};

/// A BOOL VAR_INPUT.
inline FunctionParameter bool_parameter(std::string name) {
    return {std::move(name), "BOOL", Passed::Value, vm::Scalar::Bool};
}

/// `FUNCTION name : BOOL` with these parameters, in this order.
struct FunctionInterface {
    std::string name;
    std::vector<FunctionParameter> parameters;

    /// The declaration without statements: a native function in a linked library.
    std::string declaration() const;
    vm::NativeSignature signature() const;
    /// Where parameter `parameter` starts in the argument block (an ANY or ARRAY[*] takes two
    /// places: the address, then the descriptor).
    std::size_t position(std::size_t parameter) const;
};

} // namespace eposp::plctest
