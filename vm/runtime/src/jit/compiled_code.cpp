#include "compiled_code.hpp"

#include "../run_end.hpp"
#include "jit_context.hpp"

#include <xbyak/xbyak.h>

namespace eposp::vm::jit {

CompiledCode::~CompiledCode() = default;

RunState CompiledCode::run(const Program& program, std::span<std::uint8_t> memory, TaskState& task,
                           std::uint64_t slice) const {
    const Image& image = program.image();
    const std::uint64_t limit = detail::begin_run(task, slice);

    std::uint8_t* const mem = memory.data();
    JitContext context;
    StepContext& step = context.step;
    detail::activation_bases(step.base, mem, task.current, frame_sizes_[task.current.pou]);
    step.mem = mem;
    step.mem_size = memory.size();
    step.arrays = image.arrays.data();
    step.program = &program;
    step.task = &task;
    step.code = code_.data();
    context.calls = task.calls.data();
    context.depth = &task.depth;
    context.stack_end = task.stack_end;
    context.entries = entries_.data();
    context.frame_sizes = frame_sizes_.data();
    context.remaining = static_cast<std::int64_t>(limit);

    enter_(&context, entries_[task.current.pc]);

    const auto executed =
        static_cast<std::uint64_t>(static_cast<std::int64_t>(limit) - context.remaining);
    switch (context.exit_kind) {
    case ExitKind::Finished:
        return detail::end_finished(task, executed);
    case ExitKind::Suspended:
        return detail::end_suspended(
            task, image, executed,
            Activation{context.exit_pc, context.exit_pou,
                       static_cast<std::uint32_t>(step.base[static_cast<int>(Base::Frame)] - mem),
                       static_cast<std::uint32_t>(step.base[static_cast<int>(Base::Self)] - mem)});
    case ExitKind::Trapped:
        break;
    }
    return detail::end_faulted(task, image, executed, static_cast<Trap>(context.exit_trap),
                               context.exit_pou, context.exit_pc);
}

} // namespace eposp::vm::jit
