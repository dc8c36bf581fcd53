#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <cstdint>
#include <string_view>
#include <vector>

namespace eposp::device {

/// The bytes a variable of `type` holds for `text`, an IEC 61131-3 literal (little-endian, the
/// type's size): what a service tool writes to set or force a variable. BOOL takes TRUE, FALSE,
/// 1 or 0; integers 42, -7, 16#FF, 2#1010, 8#17 (with `_` separators and an optional type
/// prefix such as INT#); an enumeration its values' names (Travel, or Mode#Travel) or numbers;
/// REAL and LREAL 1.5, -2.0E3. Values out of the type's range are refused, as are TIME and date
/// types, strings, characters and structured values (set those element by element in the
/// program, or by their elements' paths).
core::Result<std::vector<std::uint8_t>> parse_value(const vm::TypeDescriptor& type,
                                                    std::string_view text);

} // namespace eposp::device
