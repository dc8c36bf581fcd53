#include "call_graph.hpp"

#include <algorithm>
#include <unordered_set>

namespace eposp::compiler::checks {

CallGraph::CallGraph(const types::TypedProgram& program,
                     std::span<const ast::CompilationUnit> units, std::size_t linked) {
    for (const ast::CompilationUnit& unit : units.last(linked)) {
        for (const ast::Pou& pou : unit.pous) {
            library_.insert(&pou);
        }
    }
    for (const ast::CompilationUnit& unit : units.first(units.size() - linked)) {
        for (const ast::Pou& pou : unit.pous) {
            pous_.push_back(&pou);
        }
    }
    std::unordered_set<const ast::Pou*> listed(pous_.begin(), pous_.end());
    // pous_ grows while it is walked: a library POU joins when first called.
    for (std::size_t next = 0; next < pous_.size(); ++next) {
        const ast::Pou& caller = *pous_[next];
        std::vector<const ast::Pou*>& callees = callees_[&caller];
        const BodyNodes& body = bodies_.try_emplace(&caller, caller.body).first->second;
        for (const ast::Expression* call : body.calls()) {
            const types::CallTarget* target = program.call_target(*call);
            if (target == nullptr || target->pou == nullptr ||
                (target->kind != types::CallKind::Function &&
                 target->kind != types::CallKind::FunctionBlock)) {
                continue;
            }
            const ast::Pou* callee = target->pou;
            if (std::find(callees.begin(), callees.end(), callee) == callees.end()) {
                callees.push_back(callee);
            }
            // A library POU without statements is native: there is no body to check.
            if (library_.contains(callee) && !callee->body.empty() &&
                listed.insert(callee).second) {
                pous_.push_back(callee);
            }
        }
    }
}

const std::vector<const ast::Pou*>& CallGraph::callees(const ast::Pou& pou) const {
    static const std::vector<const ast::Pou*> none;
    const auto found = callees_.find(&pou);
    return found != callees_.end() ? found->second : none;
}

} // namespace eposp::compiler::checks
