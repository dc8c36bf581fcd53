#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/source_manager.hpp"

#include <string>

namespace eposp::compiler::test {

/// One source text parsed, with everything a test may want to look at.
struct Parsed {
    SourceManager sources;
    Diagnostics diagnostics;
    ast::CompilationUnit unit;

    /// All diagnostics rendered as the user sees them.
    std::string rendered() const { return render(diagnostics, sources); }
    /// The first diagnostic's message, empty when there is none.
    std::string first_message() const;
};

Parsed parse_text(const std::string& text, const std::string& path = "test.st");

/// The statements `body` inside a PROGRAM, as S-expressions separated by spaces; the test
/// fails when the text does not parse cleanly.
std::string statements_sexpr(const std::string& body);
/// The expression `text` as an S-expression (parsed as the value of an assignment).
std::string expression_sexpr(const std::string& text);
/// The message of the first error found in `body` inside a PROGRAM (empty if none).
std::string statement_error(const std::string& body);

} // namespace eposp::compiler::test
