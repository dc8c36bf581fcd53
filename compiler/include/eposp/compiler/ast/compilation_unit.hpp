#pragma once

#include "eposp/compiler/ast/declarations.hpp"
#include "eposp/compiler/source_location.hpp"

#include <vector>

namespace eposp::compiler::ast {

/// Everything declared in one source file.
struct CompilationUnit {
    FileId file = 0;
    std::vector<TypeDeclaration> types;
    std::vector<Pou> pous;
    std::vector<Configuration> configurations;
    /// VAR_GLOBAL sections outside any POU or configuration (CODESYS global variable lists):
    /// visible in every POU of the program.
    std::vector<DeclarationSection> global_variable_lists;
};

} // namespace eposp::compiler::ast
