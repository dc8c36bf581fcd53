#pragma once

#include "eposp/compiler/ast/declarations.hpp"
#include "eposp/compiler/ast/node_arena.hpp"
#include "eposp/compiler/source_location.hpp"

#include <memory>
#include <vector>

namespace eposp::compiler::ast {

/// Everything declared in one source file.
struct CompilationUnit {
    FileId file = 0;
    /// Where the nodes below were made (null when there are none): declared before them, so
    /// freed after them. A node moved out of the unit must not outlive it.
    std::unique_ptr<NodeArena> nodes;
    std::vector<TypeDeclaration> types;
    std::vector<Pou> pous;
    std::vector<Configuration> configurations;
    /// VAR_GLOBAL sections outside any POU or configuration (CODESYS global variable lists):
    /// visible in every POU of the program.
    std::vector<DeclarationSection> global_variable_lists;
};

} // namespace eposp::compiler::ast
