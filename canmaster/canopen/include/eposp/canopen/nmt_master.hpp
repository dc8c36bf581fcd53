#pragma once

#include "eposp/can/port.hpp"
#include "eposp/canopen/nmt_protocol.hpp"

namespace eposp::canopen {

/// Sends NMT node control commands (CiA 301 7.2.8.3.1) to one slave or to all.
class NmtMaster {
public:
    explicit NmtMaster(can::Port& port) : port_(port) {}

    /// `node` 1..127, or kAllNodes; above 127 is a programming error (std::invalid_argument).
    can::SendStatus send(NmtCommand command, NodeId node = kAllNodes);

private:
    can::Port& port_;
};

} // namespace eposp::canopen
