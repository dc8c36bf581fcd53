#pragma once

#include "eposp/compiler/source_location.hpp"

#include <cstdint>
#include <vector>

namespace eposp::compiler::ast {

/// `%IX0.0`, `%QW4`, `%MD10`, `%I*` (ed. 3, 6.5.5).
struct DirectAddress {
    enum class Area { Input, Output, Memory };
    /// X (bit), B, W, D, L; `None` when no size prefix is written (a bit).
    enum class Size { None, Bit, Byte, Word, DoubleWord, LongWord };
    Area area = Area::Input;
    Size size = Size::None;
    std::vector<std::uint32_t> path; // empty for the unspecified `*`
    SourceRange range;
};

} // namespace eposp::compiler::ast
