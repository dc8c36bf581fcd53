#include "eposp/canopen/nmt_slave.hpp"

#include "eposp/canopen/nmt_protocol.hpp"

namespace eposp::canopen {
namespace {

bool valid_node_id(NodeId node) {
    return node >= 1 && node <= kMaxNodeId;
}

} // namespace

NmtSlave::NmtSlave(can::Port& port, NodeId node_id, ResetHandlers handlers)
    : port_(port), node_id_(node_id), handlers_(std::move(handlers)) {}

void NmtSlave::boot() {
    reset(true);
}

void NmtSlave::on_frame(const can::Frame& frame) {
    // CiA 301 7.2.8.3.1: COB-ID 0, two bytes; node-ID 0 addresses every slave.
    if (frame.id != kNmtCanId || frame.extended || frame.remote || frame.error || frame.dlc != 2) {
        return;
    }
    const std::uint8_t specifier = frame.data[0];
    const NodeId target = frame.data[1];
    if (!is_nmt_command(specifier) || (target != kAllNodes && target != node_id_)) {
        return;
    }
    // While initialising, the node does not take part in communication (EPOS2 FW spec 7.3).
    if (state_ == NmtState::Initialising) {
        return;
    }
    apply(static_cast<NmtCommand>(specifier));
}

void NmtSlave::apply(NmtCommand command) {
    switch (command) {
    case NmtCommand::Start: // transitions 3, 6
        enter(NmtState::Operational);
        return;
    case NmtCommand::Stop: // transitions 5, 8
        enter(NmtState::Stopped);
        return;
    case NmtCommand::EnterPreOperational: // transitions 4, 7
        enter(NmtState::PreOperational);
        return;
    case NmtCommand::ResetNode: // transitions 9, 10, 11
        reset(true);
        return;
    case NmtCommand::ResetCommunication: // transitions 12, 13, 14
        reset(false);
        return;
    }
}

void NmtSlave::on_state_change(StateListener listener) {
    listeners_.push_back(std::move(listener));
}

void NmtSlave::reset(bool application) {
    enter(NmtState::Initialising);
    if (application && handlers_.application) {
        handlers_.application();
    }
    if (handlers_.communication) {
        handlers_.communication();
    }
    if (!valid_node_id(node_id_)) {
        return;
    }
    // CiA 301 7.2.8.3.2.3: the boot-up message is the heartbeat of state initialising.
    port_.send(can::Frame::data_frame(error_control_can_id(node_id_),
                                      {static_cast<std::uint8_t>(NmtState::Initialising)}));
    enter(NmtState::PreOperational); // transition 2
}

void NmtSlave::enter(NmtState state) {
    if (state == state_ && state != NmtState::Initialising) {
        return;
    }
    state_ = state;
    // By index: a listener may add another.
    for (std::size_t i = 0; i < listeners_.size(); ++i) {
        listeners_[i](state);
    }
}

} // namespace eposp::canopen
