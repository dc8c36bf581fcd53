#include "run_end.hpp"

#include <algorithm>

namespace eposp::vm::detail {
namespace {

std::uint32_t line_at(const Pou& pou, std::uint32_t instruction) {
    std::uint32_t line = 0;
    for (const auto& entry : pou.lines) {
        if (entry.instruction > instruction) {
            break;
        }
        line = entry.line;
    }
    return line;
}

} // namespace

std::uint64_t begin_run(TaskState& task, std::uint64_t slice) {
    task.fault.native_reason.clear();
    const std::uint64_t budget_left = task.budget > task.executed ? task.budget - task.executed : 0;
    return std::min({slice, budget_left, std::uint64_t{INT64_MAX}});
}

void activation_bases(std::uint8_t* (&base)[4], std::uint8_t* mem, const Activation& at,
                      std::uint32_t frame_size) {
    base[static_cast<int>(Base::Static)] = mem;
    base[static_cast<int>(Base::Frame)] = mem + at.frame;
    base[static_cast<int>(Base::Self)] = mem + at.self;
    base[static_cast<int>(Base::Out)] = mem + at.frame + frame_size;
}

RunState end_finished(TaskState& task, std::uint64_t executed) {
    task.executed += executed;
    task.state = RunState::Finished;
    return task.state;
}

RunState end_suspended(TaskState& task, const Image& image, std::uint64_t executed,
                       const Activation& at) {
    task.executed += executed;
    task.current = at;
    if (task.executed >= task.budget) {
        return end_faulted(task, image, 0, Trap::BudgetExceeded, at.pou, at.pc);
    }
    task.state = RunState::Suspended;
    return task.state;
}

RunState end_faulted(TaskState& task, const Image& image, std::uint64_t executed, Trap trap,
                     std::uint32_t pou, std::uint32_t instruction) {
    task.executed += executed;
    // In a body copied in place of a call, the error is the callee's, at its own line.
    for (const InlinedCall& call : image.pous[pou].inlined) {
        if (instruction >= call.begin && instruction < call.end) {
            instruction = image.pous[call.callee].code_begin + (instruction - call.begin);
            pou = call.callee;
            break;
        }
    }
    task.fault.trap = trap;
    task.fault.pou = pou;
    task.fault.instruction = instruction;
    task.fault.line = line_at(image.pous[pou], instruction);
    task.state = RunState::Faulted;
    return task.state;
}

} // namespace eposp::vm::detail
