#include "execute_block.hpp"

namespace eposp::plcopen::blocks {

std::vector<BlockVariable> execute_outputs(std::string_view done, bool abortable) {
    std::vector<BlockVariable> variables{output(done, "BOOL"), output("Busy", "BOOL")};
    if (abortable) {
        variables.push_back(output("Active", "BOOL"));
        variables.push_back(output("CommandAborted", "BOOL"));
    }
    variables.push_back(output("Error", "BOOL"));
    variables.push_back(output("ErrorID", "WORD"));
    variables.push_back(state("Work", "UDINT"));
    variables.push_back(state("ExecuteBefore", "BOOL"));
    if (done == "InVelocity") {
        variables.push_back(state("InVelocityShown", "BOOL"));
    }
    return variables;
}

namespace {

/// The index of an output some Execute blocks have; 0 (Axis or Execute) when this one has not.
std::size_t optional_field(const BlockInterface& interface, std::string_view name) {
    return find_field(interface, name).value_or(0);
}

} // namespace

ExecuteOutputs::ExecuteOutputs(const BlockInterface& interface)
    : execute(field(interface, "Execute")),
      done_output(optional_field(interface, "InVelocity") != 0 ? field(interface, "InVelocity")
                                                               : field(interface, "Done")),
      busy(field(interface, "Busy")), error_output(field(interface, "Error")),
      error_id(field(interface, "ErrorID")), work(field(interface, "Work")),
      before(field(interface, "ExecuteBefore")), active(optional_field(interface, "Active")),
      aborted_output(optional_field(interface, "CommandAborted")),
      shown(optional_field(interface, "InVelocityShown")) {}

void ExecuteOutputs::clear(vm::NativeBlock& block) const {
    set_flag(block, done_output, false);
    set_flag(block, error_output, false);
    block.set<std::uint16_t>(error_id, 0);
    if (aborted_output != 0) {
        set_flag(block, aborted_output, false);
    }
    if (shown != 0) {
        set_flag(block, shown, false);
    }
}

bool ExecuteOutputs::begin(vm::NativeBlock& block) const {
    const bool on = flag(block, execute);
    const bool rising = on && !flag(block, before);
    set_flag(block, before, on);
    const bool is_busy = flag(block, busy);
    const bool ended = (!is_busy && flag(block, done_output)) || flag(block, error_output) ||
                       (aborted_output != 0 && flag(block, aborted_output));
    if (!on && ended) {
        clear(block);
    }
    if (rising && !is_busy) {
        clear(block);
        return true;
    }
    return false;
}

void ExecuteOutputs::end(vm::NativeBlock& block, std::size_t output, ErrorId error) const {
    set_flag(block, busy, false);
    if (active != 0) {
        set_flag(block, active, false);
    }
    set_flag(block, done_output, false);
    set_flag(block, output, true);
    block.set<std::uint16_t>(error_id, static_cast<std::uint16_t>(error));
}

std::optional<SdoReply> followed_reply(vm::NativeBlock& block, const ExecuteOutputs& out,
                                       SdoRequests& requests) {
    if (!flag(block, out.busy)) {
        return std::nullopt;
    }
    const std::uint32_t request = block.get<std::uint32_t>(out.work);
    auto reply = requests.take(request);
    if (!reply && !requests.pending(request)) {
        out.failed(block, ErrorId::SdoAbort);
    }
    return reply;
}

ExecuteBlock::ExecuteBlock(const BlockInterface& interface, Submit submit, bool stops)
    : outputs_(interface), submit_(std::move(submit)), stops_(stops) {}

void ExecuteBlock::operator()(vm::NativeBlock& block, MotionLibrary& library) const {
    const ExecuteOutputs& out = outputs_;
    if (out.begin(block)) {
        AxisDriver* axis = referenced_axis(block, library);
        const Submitted submitted =
            axis != nullptr ? submit_(*axis, block) : Submitted{.error = ErrorId::UnknownAxis};
        block.set<std::uint32_t>(out.work, submitted.id);
        if (submitted.error != ErrorId::None) {
            out.failed(block, submitted.error);
            return;
        }
        set_flag(block, out.busy, true);
    }
    const CommandId command = block.get<std::uint32_t>(out.work);
    if (command == 0) {
        return;
    }
    const bool execute = flag(block, out.execute);
    AxisDriver& axis = library.axis(static_cast<AxisNumber>(command >> 24));
    axis.poll();
    if (flag(block, out.busy)) {
        if (stops_ && !execute) {
            axis.release_stop(command);
        }
        follow(block, axis, execute);
    } else if (stops_ && !execute) {
        axis.release_stop(command); // the stop is done and its Execute fell: Standstill
        block.set<std::uint32_t>(out.work, 0);
    }
}

void ExecuteBlock::follow(vm::NativeBlock& block, AxisDriver& axis, bool execute) const {
    const ExecuteOutputs& out = outputs_;
    const CommandReport report = axis.report(block.get<std::uint32_t>(out.work));
    switch (report.status) {
    case CommandStatus::Buffered:
    case CommandStatus::Active:
        if (out.active != 0) {
            set_flag(block, out.active, report.status == CommandStatus::Active);
        }
        if (out.shown != 0) {
            // InVelocity: held while Execute is TRUE, else shown for one call.
            const bool show = report.in_velocity && (execute || !flag(block, out.shown));
            set_flag(block, out.done_output, show);
            set_flag(block, out.shown, report.in_velocity);
        }
        return;
    case CommandStatus::Done:
        out.done(block);
        break;
    case CommandStatus::Aborted:
    case CommandStatus::Unknown:
        if (out.aborted_output != 0) {
            out.aborted(block);
            break;
        }
        [[fallthrough]];
    case CommandStatus::Failed:
        out.failed(block, report.error);
        break;
    }
    if (!stops_) {
        block.set<std::uint32_t>(out.work, 0);
    }
}

} // namespace eposp::plcopen::blocks
