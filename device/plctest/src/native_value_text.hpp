#pragma once

// Comparing and showing the values the assertions receive (vm::NativeValue: an ANY input, an
// element of an ARRAY[*], or a typed input seen the same way).

#include "eposp/vm/native_values.hpp"

#include <string>

namespace eposp::plctest {

/// The value as an ST literal: `TRUE`, `-5`, `255`, `16#00FF` (a bit string), `1.5`, `T#1s500ms`,
/// `D#2024-01-31`, `'text'`.
std::string literal(const vm::NativeValue& value);

/// Whether `expected` and `actual` are equal as AssertEquals sees them: numbers by value
/// (a DINT 5 equals a USINT 5 and a REAL 5.0), strings by their text, times and dates by value
/// within their own kind, BOOL with BOOL. Values of kinds that do not compare (a TIME and a
/// DINT, a STRING and a number) are not equal, and `types_differ` says so.
struct Comparison {
    bool equal = false;
    bool types_differ = false;
};
Comparison compare(const vm::NativeValue& expected, const vm::NativeValue& actual);

} // namespace eposp::plctest
