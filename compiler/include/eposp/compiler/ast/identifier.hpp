#pragma once

#include "eposp/compiler/source_location.hpp"

#include <string>

namespace eposp::compiler::ast {

/// A name as written in the source (IEC identifiers compare case-insensitively; the original
/// spelling is kept for messages).
struct Identifier {
    std::string name;
    SourceRange range;
};

} // namespace eposp::compiler::ast
