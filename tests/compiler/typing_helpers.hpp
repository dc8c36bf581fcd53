#pragma once

// Runs the front end (parse, names, types) on ST source and finds expressions in it, for the
// tests of the typing stage.

#include "eposp/compiler/types/front_end.hpp"

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace eposp::compiler::test {

struct Typed {
    SourceManager sources;
    Diagnostics diagnostics;
    std::unique_ptr<types::FrontEnd> front_end;

    /// The rendered diagnostics.
    std::string errors() const;
    const types::TypedProgram& program() const { return *front_end->program; }
    /// The value of the `n`th statement (from 0) of the last POU, an assignment.
    const ast::Expression& value(std::size_t n) const;
    /// The name of the type of that value ("" when it has none).
    std::string type_of(std::size_t n) const;
};

/// The front end over `source`.
std::unique_ptr<Typed> type_source(const std::string& source);

/// `source` as the body of `PROGRAM Main` with `declarations` in its VAR section.
std::unique_ptr<Typed> type_body(const std::string& declarations, const std::string& body);

/// The codes of `diagnostics` ("E0301"), in the order reported.
std::vector<std::string> codes_of(const Diagnostics& diagnostics);

/// A named program (or a body) and the errors the typing stage must give it.
struct TypingCase {
    std::string name;
    std::string source;
    std::vector<std::string> codes; // in the order reported
};

void PrintTo(const TypingCase& c, std::ostream* out);

} // namespace eposp::compiler::test
