#pragma once

// The value an initial value gives a variable, as the image holds it (IEC 61131-3 ed. 3,
// 6.5.1.3 and 6.4.2: an initial value is a constant expression of the variable's type). One
// function for both stages that need it: the typing stage reports what it refuses
// (types/initializers.cpp), code generation writes the bytes (codegen/initial_values.cpp).

#include "constant_evaluator.hpp"
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

/// The bytes of `expression` as a constant of `type`, as `constants` evaluates it: literals,
/// enumeration values, CONSTANTs (VAR CONSTANT, VAR_GLOBAL CONSTANT) with a plain initial value,
/// signs, + - * / (and MOD on integers) of those, NOT AND OR XOR on BOOLs and integers (NOT on
/// literals and constants of the variable's type); durations and dates (but TIME_OF_DAY, which
/// wraps at midnight) plus or minus a duration, a duration times or divided by an integer (`T#1ms *
/// 4`), as the VM computes them (a REAL factor rounds at run time and is no constant here).
std::variant<std::vector<std::uint8_t>, ConstantRefusal>
constant_bytes(const ast::Expression& expression, const sema::Type& type,
               const ConstantEvaluator& constants);

/// `value`'s low `size` bytes, little-endian.
std::vector<std::uint8_t> integer_bytes(std::int64_t value, std::uint32_t size);

} // namespace eposp::compiler::types
