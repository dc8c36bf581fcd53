#include "eposp/canopen/emcy_consumer.hpp"

#include "eposp/canopen/cob_id.hpp"
#include "eposp/canopen/nmt_protocol.hpp"

#include <algorithm>

namespace eposp::canopen {

void EmcyConsumer::on_frame(const can::Frame& frame) {
    if ((state_ != NmtState::PreOperational && state_ != NmtState::Operational) || frame.extended ||
        frame.remote || frame.error || frame.dlc != 8 || frame.id <= kEmcyCanIdBase ||
        frame.id > kEmcyCanIdBase + kMaxNodeId) {
        return;
    }
    Emergency emergency{
        .node = static_cast<NodeId>(frame.id - kEmcyCanIdBase),
        .error_code = static_cast<std::uint16_t>(frame.data[0] | frame.data[1] << 8),
        .error_register = frame.data[2],
    };
    std::copy_n(frame.data.begin() + 3, emergency.manufacturer_data.size(),
                emergency.manufacturer_data.begin());
    for (std::size_t i = 0; i < listeners_.size(); ++i) {
        listeners_[i](emergency);
    }
}

void EmcyConsumer::on_emergency(Listener listener) {
    listeners_.push_back(std::move(listener));
}

} // namespace eposp::canopen
