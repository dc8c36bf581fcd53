#pragma once

#include "eposp/compiler/diagnostics.hpp"

#include <Token.h>
#include <vector>

namespace eposp::compiler {

/// Implementation limits (IEC 61131-3 ed. 3 leaves them to the implementer): how deeply
/// parentheses, brackets, control statements and structures may nest, how many prefix operators
/// or type constructors (`REF_TO`, `ARRAY ... OF`) may be chained, and how many binary
/// operators one statement may hold. The parser and every walk over the tree recurse once per
/// level, so the limits keep any input, however hostile, within the stack.
struct NestingLimits {
    std::size_t depth = 256;
    std::size_t chain = 256;
    std::size_t operators_per_statement = 4096;
};

/// Checks the token stream before parsing. Reports the first token past a limit and returns
/// false; the file is then not parsed.
bool check_nesting(const std::vector<antlr4::Token*>& tokens, FileId file, Diagnostics& diagnostics,
                   const NestingLimits& limits = {});

} // namespace eposp::compiler
