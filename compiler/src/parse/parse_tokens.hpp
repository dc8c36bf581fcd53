#pragma once

#include "StructuredTextParser.h"
#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"

#include <CommonTokenStream.h>
#include <TokenSource.h>
#include <vector>

namespace eposp::compiler {

/// `parse()` from the tokens on: the lexical checks, parsing and the AST. Apart so that a test
/// can run it on the tokens of ANTLR's generated lexer too. The hand-written `Lexer`'s tokens
/// are taken as `parse()` takes them, into one array; any other source's through the token
/// stream, so that a test comparing the two compares both ways of holding them.
ast::CompilationUnit parse_tokens(antlr4::TokenSource& lexer, FileId file,
                                  Diagnostics& diagnostics);

/// The lexical errors and implementation limits of a whole file's tokens, checked before it is
/// parsed; false when it is not to be parsed.
bool check_tokens(const std::vector<antlr4::Token*>& tokens, FileId file, Diagnostics& diagnostics);

/// The generated parser over the whole token stream with full LL prediction and our messages and
/// recovery (`SyntaxErrorStrategy`): the syntax errors of a file the hand-written parser refused.
/// Its tree is what the parser's oracle in tests builds the AST from.
generated::StructuredTextParser::CompilationUnitContext*
parse_with_recovery(generated::StructuredTextParser& parser, FileId file, Diagnostics& diagnostics);

} // namespace eposp::compiler
