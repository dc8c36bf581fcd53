#include "eposp/vm/machine.hpp"

#include "interpreter.hpp"
#include "jit/compiled_code.hpp"

#include <algorithm>

namespace eposp::vm {

std::string_view trap_name(Trap trap) {
    switch (trap) {
    case Trap::DivisionByZero:
        return "division by zero";
    case Trap::IndexOutOfRange:
        return "array index out of range";
    case Trap::NullDereference:
        return "NULL dereference";
    case Trap::InvalidAddress:
        return "invalid address";
    case Trap::BudgetExceeded:
        return "instruction budget exceeded";
    case Trap::StackOverflow:
        return "stack overflow";
    case Trap::NativeError:
        return "native function failed";
    case Trap::SubrangeViolation:
        return "value out of subrange";
    }
    return "?";
}

Machine::Machine(const Program& program, Coverage coverage) : program_(program) {
    if (coverage == Coverage::Record) {
        coverage_ = std::make_unique<detail::CoverageCounters>(program.image());
    }
    const auto& image = program.image();
    std::uint32_t end = image.static_size;
    for (const auto& task : image.tasks) {
        TaskState state;
        state.stack_begin = end;
        end += task.stack_size;
        state.stack_end = end;
        tasks_.push_back(std::move(state));
    }
    memory_.resize(end);
    cold_start();
}

Machine::~Machine() = default;
Machine::Machine(Machine&&) noexcept = default;

CoverageReport Machine::coverage() const {
    return coverage_ ? detail::coverage_report(program_.image(), *coverage_) : CoverageReport{};
}

void Machine::cold_start() {
    const auto& init = program_.image().static_init;
    std::copy(init.begin(), init.end(), memory_.begin());
    std::fill(memory_.begin() + static_cast<std::ptrdiff_t>(init.size()), memory_.end(), 0);
    for (auto& task : tasks_) {
        task.state = RunState::Idle;
        task.depth = 0;
    }
}

void Machine::start(std::size_t task, std::size_t entry) {
    auto& state = tasks_.at(task);
    const auto& spec = program_.image().tasks.at(task).entries.at(entry);
    const auto& pou = program_.image().pous[spec.pou];
    state.current = Activation{pou.code_begin, spec.pou, state.stack_begin, spec.instance};
    state.depth = 0;
    state.executed = 0;
    state.state = RunState::Suspended;
}

RunState Machine::run(std::size_t task, std::uint64_t slice) {
    auto& state = tasks_.at(task);
    if (state.state != RunState::Suspended) {
        return state.state;
    }
    if (coverage_) {
        return detail::execute(program_, memory_, state, slice, coverage_.get());
    }
    if (const auto* compiled = program_.compiled()) {
        return compiled->run(program_, memory_, state, slice);
    }
    return detail::execute(program_, memory_, state, slice);
}

RunState Machine::run_cycle(std::size_t task) {
    const auto entries = program_.image().tasks.at(task).entries.size();
    for (std::size_t entry = 0; entry < entries; ++entry) {
        start(task, entry);
        if (run(task) == RunState::Faulted) {
            return RunState::Faulted;
        }
    }
    return RunState::Finished;
}

void Machine::set_budget(std::size_t task, std::uint64_t instructions) {
    tasks_.at(task).budget = instructions;
}

std::string Machine::describe_fault(std::size_t task) const {
    const auto& fault = tasks_.at(task).fault;
    std::string text(trap_name(fault.trap));
    if (!fault.native_reason.empty()) {
        text += ": " + fault.native_reason;
    }
    text += " in " + program_.image().pous[fault.pou].name;
    if (fault.line != 0) {
        text += " at line " + std::to_string(fault.line);
    }
    return text;
}

} // namespace eposp::vm
