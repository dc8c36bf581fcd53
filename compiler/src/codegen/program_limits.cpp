// The image limits (eposp/vm/image_limits.hpp) checked at compile time, each with the limit in
// its message, so that the loader never refuses what the compiler built.
#include "eposp/vm/image_limits.hpp"
#include "program_generator.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <functional>

namespace eposp::compiler::codegen {

void ProgramGenerator::check_limits() {
    if (builder_.static_size() > vm::kMaxAreaSize) {
        diagnostics_.error(DiagnosticCode::E0502, {},
                           fmt::format("the program's static data (globals, program and FB "
                                       "instances, constants) needs {} bytes; the limit is {}",
                                       builder_.static_size(), vm::kMaxAreaSize));
    }
    const std::uint64_t stacks = stack_size() * tasks_.size();
    if (stacks > vm::kMaxAreaSize) {
        diagnostics_.error(DiagnosticCode::E0502, {},
                           fmt::format("the task stacks need {} bytes ({} per task, for the "
                                       "frames of every POU); the limit is {}",
                                       stacks, stack_size(), vm::kMaxAreaSize));
    }
    check_call_depth();
}

void ProgramGenerator::check_call_depth() {
    // Without recursion the calls form a DAG: the longest chain of calls below a POU, memoised.
    std::unordered_map<const ast::Pou*, std::uint32_t> depths;
    std::function<std::uint32_t(const ast::Pou*)> depth = [&](const ast::Pou* pou) {
        if (const auto it = depths.find(pou); it != depths.end()) {
            return it->second;
        }
        std::uint32_t deepest = 0;
        if (const auto it = calls_.find(pou); it != calls_.end()) {
            for (const ast::Pou* callee : it->second) {
                deepest = std::max(deepest, depth(callee) + 1);
            }
        }
        return depths[pou] = deepest;
    };
    for (const auto& [pou, callees] : calls_) {
        if (const std::uint32_t nesting = depth(pou); nesting > vm::kMaxCallDepth) {
            diagnostics_.error(DiagnosticCode::E0503, pou->name.range,
                               fmt::format("calls from '{}' nest {} deep; the limit is {}",
                                           pou->name.name, nesting, vm::kMaxCallDepth));
            return; // the POUs it calls nest deeply too: one message says it
        }
    }
}

} // namespace eposp::compiler::codegen
