#pragma once

// Copying located variables (`AT %IW4`, `AT %MX2.1`) between an I/O area and VM memory: the one
// place that knows how a binding's bytes and bits sit in an area, shared by the process image
// and the marker area. The bindings must have been checked against the area's size.

#include "eposp/vm/image.hpp"

#include <cstdint>
#include <span>

namespace eposp::vm::detail {

/// Bytes a binding occupies in its area (one for a %X bit).
std::uint32_t binding_size(const IoBinding& binding);

/// The area's bytes into the variable (a %X bit as BOOL 0/1).
void copy_into_variable(std::span<const std::uint8_t> area, const IoBinding& binding,
                        std::span<std::uint8_t> memory);
/// The variable into the area's bytes (a %X bit set or cleared, the other bits kept).
void copy_into_area(std::span<std::uint8_t> area, const IoBinding& binding,
                    std::span<const std::uint8_t> memory);
/// The binding's bytes (or bit) in the area to zero.
void clear_in_area(std::span<std::uint8_t> area, const IoBinding& binding);

} // namespace eposp::vm::detail
