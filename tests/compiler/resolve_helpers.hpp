#pragma once

#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/sema/semantic_model.hpp"
#include "eposp/compiler/source_manager.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace eposp::compiler::test {

/// Source files parsed and resolved together, as one program.
struct Resolved {
    SourceManager sources;
    Diagnostics diagnostics;
    std::vector<ast::CompilationUnit> units;
    sema::SemanticModel model;

    std::string rendered() const { return render(diagnostics, sources); }
    /// Every diagnostic's message, in order.
    std::vector<std::string> messages() const;
    /// What the target of assignment `index` in the body of the first POU of file 0 names.
    const sema::Symbol* assignment_target(std::size_t index) const;
    /// What the value of assignment `index` in the body of the first POU of file 0 names.
    const sema::Symbol* assignment_value(std::size_t index) const;
};

/// Parses each (path, text) file and resolves them together; the test fails on syntax errors.
std::unique_ptr<Resolved>
resolve_files(const std::vector<std::pair<std::string, std::string>>& files);
std::unique_ptr<Resolved> resolve_text(const std::string& text);

} // namespace eposp::compiler::test
