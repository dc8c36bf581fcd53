#include "eposp/canopen/nmt_master.hpp"

#include "eposp/canopen/nmt_protocol.hpp"

#include <stdexcept>

namespace eposp::canopen {

can::SendStatus NmtMaster::send(NmtCommand command, NodeId node) {
    if (node > kMaxNodeId) {
        throw std::invalid_argument("NmtMaster::send: node-ID above 127");
    }
    return port_.send(
        can::Frame::data_frame(kNmtCanId, {static_cast<std::uint8_t>(command), node}));
}

} // namespace eposp::canopen
