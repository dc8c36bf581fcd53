#pragma once

#include "eposp/compiler/source_location.hpp"

#include <Token.h>

namespace eposp::compiler {

/// The source range of one token: ANTLR counts lines from 1 and columns from 0, in code points.
SourceRange token_range(FileId file, const antlr4::Token& token);
/// From the first character of `first` to the last of `last`.
SourceRange token_range(FileId file, const antlr4::Token& first, const antlr4::Token& last);
/// The single column just after `token`, where a missing ';' or keyword belongs.
SourceRange range_after(FileId file, const antlr4::Token& token);

} // namespace eposp::compiler
