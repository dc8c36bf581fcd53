#include "run_end.hpp"

#include "source_location.hpp"

#include <algorithm>
#include <optional>

namespace eposp::vm::detail {

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
    // A native function block's body has no source: its failure is at its call, copied in
    // place or called, and the reason names the block.
    std::optional<std::uint32_t> native = locate(image, pou, instruction);
    if (trap == Trap::NativeError && !native && image.pous[pou].lines.empty() && task.depth > 0) {
        native = pou;
        const Activation& caller = task.calls[task.depth - 1];
        pou = caller.pou;
        instruction = caller.pc - 1;
        locate(image, pou, instruction);
    }
    if (trap == Trap::NativeError && native) {
        task.fault.native_reason = image.pous[*native].name + ": " + task.fault.native_reason;
    }
    task.fault.trap = trap;
    task.fault.pou = pou;
    task.fault.instruction = instruction;
    task.fault.line = line_at(image.pous[pou], instruction);
    task.state = RunState::Faulted;
    return task.state;
}

} // namespace eposp::vm::detail
