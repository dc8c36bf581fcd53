#pragma once

// Which POU calls which, from the call targets the typing stage found: what the recursion
// check walks and what decides which library POUs are checked at all. The nodes of each body,
// listed to find its calls, are kept for the checks (body_nodes.hpp).

#include "body_nodes.hpp"
#include "eposp/compiler/ast/compilation_unit.hpp"
#include "eposp/compiler/types/typed_program.hpp"

#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace eposp::compiler::checks {

class CallGraph {
public:
    /// The POUs of the program's own files (all of `units` but the last `linked`), then the
    /// linked POUs with statements they call, directly or not.
    CallGraph(const types::TypedProgram& program, std::span<const ast::CompilationUnit> units,
              std::size_t linked);

    /// The POUs whose code runs, in the order of their files, then as first called.
    const std::vector<const ast::Pou*>& pous() const { return pous_; }
    /// Whether `pou` is among pous().
    bool runs(const ast::Pou& pou) const { return callees_.contains(&pou); }
    /// Whether `pou` is native: a POU without statements in a linked library, whose body the
    /// host provides (docs/runtime.md, "Native functions", "Native function blocks").
    bool is_native(const ast::Pou& pou) const {
        return pou.body.empty() && library_.contains(&pou);
    }
    /// The user FUNCTIONs, FBs and PROGRAMs `pou` calls, each once, as first called.
    const std::vector<const ast::Pou*>& callees(const ast::Pou& pou) const;
    /// The statements and expressions of the body of `pou`, one of pous().
    const BodyNodes& body(const ast::Pou& pou) const { return bodies_.at(&pou); }

private:
    std::unordered_set<const ast::Pou*> library_;
    std::vector<const ast::Pou*> pous_;
    std::unordered_map<const ast::Pou*, std::vector<const ast::Pou*>> callees_;
    std::unordered_map<const ast::Pou*, BodyNodes> bodies_;
};

} // namespace eposp::compiler::checks
