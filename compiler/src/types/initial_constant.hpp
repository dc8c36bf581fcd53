#pragma once

// The value an initial value gives a variable, as the image holds it (IEC 61131-3 ed. 3,
// 6.5.1.3 and 6.4.2: an initial value is a constant expression of the variable's type). One
// function for both stages that need it: the typing stage reports what it refuses
// (types/declaration_typing.cpp), code generation writes the bytes (codegen/initial_values.cpp).

#include "constant_folder.hpp"
#include "eposp/compiler/diagnostic_code.hpp"

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace eposp::compiler::types {

/// Why an expression gives no constant of a type: E0313 (not a constant of it) or E0311 (a
/// literal or folded integer that does not fit).
struct ConstantRefusal {
    DiagnosticCode code;
    std::string message;
};

/// The bytes of `expression`, typed as a value of `type`, as the image holds it: the constant
/// the typing stage recorded for it (TypedProgram::constant_of) stored into `type` (E0313 where
/// there is none; E0311 for an integer that does not fit, or that an operation wrapped), a text
/// cut at the capacity; NULL from its literal, the literal's or the CONSTANT's that it names.
std::variant<std::vector<std::uint8_t>, ConstantRefusal>
constant_bytes(const ast::Expression& expression, const sema::Type& type,
               const TypedProgram& program);

/// `value`'s low `size` bytes, little-endian.
std::vector<std::uint8_t> integer_bytes(std::int64_t value, std::uint32_t size);

} // namespace eposp::compiler::types
