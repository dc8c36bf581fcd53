#pragma once

#include "eposp/vm/image.hpp"
#include "eposp/vm/symbol_lookup.hpp"

#include <span>
#include <string>

namespace eposp::vm {

/// The value of a variable as an IEC 61131-3 literal, for watch lists and run summaries:
/// `TRUE`, `-42`, `1.5`, `T#1s500ms`, `D#2024-01-31`, `'text'`, `Travel` (an enumeration).
/// Structured values (arrays, structures, FB instances) show their type name in angle brackets;
/// watch their elements.
std::string format_value(const Image& image, std::span<const std::uint8_t> memory,
                         VariableLocation location);

/// The same for a value of the elementary or string `type` that `bytes` begins with (its name
/// tells TIME from LINT, STRING's header gives its length).
std::string format_value(const TypeDescriptor& type, std::span<const std::uint8_t> bytes);

} // namespace eposp::vm
