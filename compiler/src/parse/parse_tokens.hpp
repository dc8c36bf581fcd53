#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"

#include <TokenSource.h>

namespace eposp::compiler {

/// `parse()` from the tokens on: the lexical checks, parsing and the AST. Apart so that a test
/// can run it on the tokens of ANTLR's generated lexer too.
ast::CompilationUnit parse_tokens(antlr4::TokenSource& lexer, FileId file,
                                  Diagnostics& diagnostics);

} // namespace eposp::compiler
