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
};

} // namespace eposp::compiler::ast
