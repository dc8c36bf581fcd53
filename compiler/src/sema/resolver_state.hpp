#pragma once

// Shared between the two passes of name resolution: the declaration collector fills it, the
// name resolver reads it.
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/sema/semantic_model.hpp"

#include <string>
#include <unordered_map>
#include <vector>

namespace eposp::compiler::sema {

struct ResolverState {
    SemanticModel& model;
    Diagnostics& diagnostics;
    /// Enumeration values by folded name: an unqualified `Red` may belong to several types.
    std::unordered_map<std::string, std::vector<const Symbol*>> enum_values{};
    std::unordered_map<const ast::Pou*, Scope*> pou_scopes{}; // EXTENDS links them in pass 2
    /// Tasks and program instances of each resource (ed. 3, 6.8.2).
    std::unordered_map<const ast::Resource*, const Scope*> resource_scopes{};
    /// What program connections see (ed. 3, 6.8.2): the globals and every program instance of
    /// the configuration, whose outputs may feed another instance's inputs.
    std::unordered_map<const ast::Configuration*, const Scope*> connection_scopes{};

    /// Declares `symbol` in `scope`, or reports that its name is taken there.
    void declare(Scope& scope, const Symbol& symbol);
};

} // namespace eposp::compiler::sema
