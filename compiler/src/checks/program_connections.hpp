#pragma once

// What a program connection may name (E0423, checks/program_connections.cpp); code generation
// leaves out the connections the checks refused.

#include "eposp/compiler/ast/expressions.hpp"
#include "eposp/compiler/sema/semantic_model.hpp"
#include "eposp/compiler/sema/type_table.hpp"

namespace eposp::compiler::checks {

/// Whether a connection of a program's input (`output` false) or output may name
/// `expression`: a literal (inputs only), a variable path down from a global or a direct
/// address (no input address for an output), another program instance's output (inputs only).
bool is_connectable(const sema::SemanticModel& model, sema::TypeTable& types,
                    const ast::Expression& expression, bool output);

} // namespace eposp::compiler::checks
