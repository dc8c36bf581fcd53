#pragma once

#include <cstdint>

namespace eposp::compiler {

/// Index of a file in the SourceManager that holds it.
using FileId = std::uint32_t;

/// A point in a source file: 1-based line, 1-based column counted in characters (code points).
struct SourcePosition {
    std::uint32_t line = 0;
    std::uint32_t column = 0;

    friend bool operator==(const SourcePosition&, const SourcePosition&) = default;
};

/// The text a node or diagnostic refers to: from `begin` up to and including `end`.
struct SourceRange {
    FileId file = 0;
    SourcePosition begin;
    SourcePosition end;

    friend bool operator==(const SourceRange&, const SourceRange&) = default;
};

} // namespace eposp::compiler
