// E0407: IEC 61131-3 ed. 3, 6.6.1.1 forbids a POU to call itself, directly or through others;
// the stack size of a task is the sum of the frames because of it.

#include "pou_checks.hpp"

#include <fmt/format.h>
#include <unordered_map>

namespace eposp::compiler::checks {

void check_recursion(const CallGraph& calls, Diagnostics& diagnostics) {
    // Depth-first search for a cycle: a call back to a POU still on the path closes one.
    enum class Mark { Unvisited, Active, Done };
    std::unordered_map<const ast::Pou*, Mark> marks;
    const auto visit = [&](const auto& self, const ast::Pou* pou) -> void {
        marks[pou] = Mark::Active;
        for (const ast::Pou* callee : calls.callees(*pou)) {
            const Mark mark = marks[callee];
            if (mark == Mark::Active) {
                diagnostics.error(DiagnosticCode::E0407, callee->name.range,
                                  fmt::format("'{}' calls itself (through '{}'): recursion is "
                                              "not allowed in IEC 61131-3 (6.6.1.1)",
                                              callee->name.name, pou->name.name));
            } else if (mark == Mark::Unvisited) {
                self(self, callee);
            }
        }
        marks[pou] = Mark::Done;
    };
    for (const ast::Pou* pou : calls.pous()) {
        if (marks[pou] == Mark::Unvisited) {
            visit(visit, pou);
        }
    }
}

} // namespace eposp::compiler::checks
