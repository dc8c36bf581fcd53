#include "eposp/canopen/frame_router.hpp"

#include <algorithm>

namespace eposp::canopen {

void FrameRouter::add(KeySource keys, Handler handler) {
    receivers_.push_back({std::move(keys), std::move(handler)});
    stale_ = true;
}

void FrameRouter::rebuild() {
    table_.clear();
    ReceiveKeys keys;
    for (std::size_t receiver = 0; receiver < receivers_.size(); ++receiver) {
        keys.clear();
        receivers_[receiver].keys(keys);
        for (const ReceiveKey key : keys) {
            std::vector<std::size_t>& listed = table_[key];
            if (listed.empty() || listed.back() != receiver) {
                listed.push_back(receiver);
            }
        }
    }
    stale_ = false;
}

void FrameRouter::dispatch(const can::Frame& frame) {
    if (frame.error) {
        return;
    }
    // The table changes only here, never under a dispatch in progress (a handler that hands a
    // frame on): the list iterated below stays put.
    if (stale_ && depth_ == 0) {
        rebuild();
    }
    const auto found = table_.find(receive_key(frame));
    if (found == table_.end()) {
        return;
    }
    ++depth_;
    for (const std::size_t receiver : found->second) {
        receivers_[receiver].handler(frame);
    }
    --depth_;
}

} // namespace eposp::canopen
