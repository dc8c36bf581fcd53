#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <string_view>

namespace eposp::vm {

/// Where a variable lives: its static data offset and its type (an index into Image::types).
struct VariableLocation {
    std::uint32_t offset = 0;
    std::uint32_t type = 0;
    bool read_only = false; ///< a constant, or reached through a READ_ONLY access path
};

/// Resolves a full variable path such as `Main.counter`, `Main.axis[2].pos` or `Main.m[1, 3]`
/// through the symbol table and the type descriptors: the longest symbol that prefixes the
/// path, then fields and (bounds-checked) indices. Names compare case-insensitively, as IEC
/// identifiers do. For watch, force and debugging; the image must have passed verify.
core::Result<VariableLocation> lookup_variable(const Image& image, std::string_view path);

} // namespace eposp::vm
