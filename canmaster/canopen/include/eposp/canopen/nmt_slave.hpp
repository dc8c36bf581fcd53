#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/canopen/nmt_state.hpp"

#include <functional>
#include <vector>

namespace eposp::canopen {

/// The NMT slave state machine (CiA 301 7.3.2.2, figure 48; EPOS2 FW spec 7.3, table 7-65).
///
/// boot() is power-on: initialisation (reset application, then reset communication), the
/// boot-up message (0x700 + node-ID, one byte 0x00) and pre-operational. Then NMT commands,
/// received on COB-ID 0x000 for this node or for all, or applied by local control, move it
/// between pre-operational, operational and stopped; a command that would not change the state
/// does nothing. What a reset resets is the node's business: the NMT slave calls its handlers
/// and stays a state machine. Every change of state is told to the listeners, Initialising
/// included, so that the other services stop at a reset and start again after the boot-up.
class NmtSlave {
public:
    using StateListener = std::function<void(NmtState)>;
    using ResetHandler = std::function<void()>;

    struct ResetHandlers {
        /// Reset node only: the application area (0x2000..0x9FFF) back to its stored values.
        ResetHandler application;
        /// Both resets: the communication area (0x1000..0x1FFF) back to its stored values;
        /// a pending node-ID takes effect here (set_node_id).
        ResetHandler communication;
    };

    NmtSlave(can::Port& port, NodeId node_id, ResetHandlers handlers);
    NmtSlave(const NmtSlave&) = delete;
    NmtSlave& operator=(const NmtSlave&) = delete;

    /// Power-on (transitions 1 and 2): as reset node.
    void boot();
    /// An NMT frame; any other frame is ignored, as is a frame of the wrong length, for another
    /// node or with an unknown command specifier.
    void on_frame(const can::Frame& frame);
    /// Local control (CiA 301 7.3.2.2: "NMT service indication or local control").
    void apply(NmtCommand command);

    NmtState state() const { return state_; }
    NodeId node_id() const { return node_id_; }
    /// The node-ID of the next boot-up message and of the commands this slave obeys; called by
    /// the reset-communication handler when LSS has configured a new one. A node without a
    /// valid node-ID (1..127, e.g. LSS's 255) stays in initialisation and sends no boot-up
    /// (CiA 305).
    void set_node_id(NodeId node_id) { node_id_ = node_id; }

    void on_state_change(StateListener listener);

private:
    void reset(bool application);
    void enter(NmtState state);

    can::Port& port_;
    NodeId node_id_;
    ResetHandlers handlers_;
    NmtState state_ = NmtState::Initialising;
    std::vector<StateListener> listeners_;
};

} // namespace eposp::canopen
