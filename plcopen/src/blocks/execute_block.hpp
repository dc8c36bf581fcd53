#pragma once

#include "block_definition.hpp"

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace eposp::plcopen::blocks {

/// The outputs and state an Execute block ends with, in order: `done` (Done or InVelocity),
/// Busy, Active and CommandAborted if `abortable`, Error, ErrorID; then its state: the command
/// or request it follows, Execute of the last call and, for InVelocity, whether it was shown.
std::vector<BlockVariable> execute_outputs(std::string_view done, bool abortable);

/// The output rules every block with an Execute input shares (PLCopen Motion Control Part 1,
/// 2.4.1): a rising edge of Execute starts the block's work unless it is Busy (then the edge is
/// ignored); Done, CommandAborted and Error are exclusive, and stay set while Execute is TRUE,
/// or for one call if Execute is already FALSE.
class ExecuteOutputs {
public:
    explicit ExecuteOutputs(const BlockInterface& interface);

    /// Call first: applies the rules to the last call's outputs; true when the block starts
    /// now (its outputs cleared).
    bool begin(vm::NativeBlock& block) const;
    void done(vm::NativeBlock& block) const { end(block, done_output, ErrorId::None); }
    void aborted(vm::NativeBlock& block) const { end(block, aborted_output, ErrorId::None); }
    void failed(vm::NativeBlock& block, ErrorId error) const { end(block, error_output, error); }

    std::size_t execute, done_output, busy, error_output, error_id, work, before;
    std::size_t active = 0, aborted_output = 0, shown = 0; ///< 0: the block has none

private:
    void end(vm::NativeBlock& block, std::size_t output, ErrorId error) const;
    void clear(vm::NativeBlock& block) const;
};

/// The reply of the SDO transfer a Busy Execute block follows (its `work`), once it came; a
/// transfer forgotten meanwhile fails the block.
std::optional<SdoReply> followed_reply(vm::NativeBlock& block, const ExecuteOutputs& out,
                                       SdoRequests& requests);

/// A block that gives its axis a command (MotionCommand, MC_Reset) and follows it to its end.
class ExecuteBlock {
public:
    using Submit = std::function<Submitted(AxisDriver& axis, vm::NativeBlock& block)>;

    /// `stops`: MC_Stop, whose axis stays Stopping until Execute falls.
    ExecuteBlock(const BlockInterface& interface, Submit submit, bool stops = false);

    void operator()(vm::NativeBlock& block, MotionLibrary& library) const;

private:
    void follow(vm::NativeBlock& block, AxisDriver& axis, bool execute) const;

    ExecuteOutputs outputs_;
    Submit submit_;
    bool stops_;
};

} // namespace eposp::plcopen::blocks
