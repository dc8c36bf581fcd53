#include "eposp/canopen/frame_router.hpp"

#include <algorithm>

namespace eposp::canopen {

void FrameRouter::add(KeySource keys, void* target, Call call) {
    receivers_.push_back({std::move(keys), target, call});
    invalidate();
}

void FrameRouter::invalidate() {
    stale_ = true;
    update_filter();
}

void FrameRouter::filter(can::Port& port) {
    filtered_ = &port;
    update_filter();
}

void FrameRouter::update_filter() {
    if (filtered_ == nullptr) {
        return;
    }
    if (stale_) {
        filtered_->accept_all();
        return;
    }
    can::Port::StandardIds ids;
    for (std::size_t id = 0; id < standard_.size(); ++id) {
        ids[id] = standard_[id] != 0;
    }
    filtered_->accept_only(ids);
}

void FrameRouter::rebuild() {
    lists_.clear();
    standard_.fill(0);
    extended_.clear();
    ReceiveKeys keys;
    for (std::size_t receiver = 0; receiver < receivers_.size(); ++receiver) {
        keys.clear();
        receivers_[receiver].keys(keys);
        for (const ReceiveKey key : keys) {
            std::vector<std::size_t>& listed = list_of(key);
            if (listed.empty() || listed.back() != receiver) {
                listed.push_back(receiver);
            }
        }
    }
    stale_ = false;
    update_filter();
}

std::vector<std::size_t>& FrameRouter::list_of(ReceiveKey key) {
    const std::size_t next = lists_.size() + 1;
    std::size_t position = 0; // 1 + the list's index
    if ((key & kCobIdExtended) != 0) {
        position = extended_.try_emplace(key, next).first->second;
    } else {
        std::uint16_t& slot = standard_.at(key);
        if (slot == 0) {
            slot = static_cast<std::uint16_t>(next);
        }
        position = slot;
    }
    if (position == next) {
        lists_.emplace_back();
    }
    return lists_[position - 1];
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
    std::size_t position = 0;
    if (frame.extended) {
        const auto found = extended_.find(receive_key(frame));
        position = found == extended_.end() ? 0 : found->second;
    } else if (frame.id < standard_.size()) {
        position = standard_[frame.id];
    }
    if (position == 0) {
        return;
    }
    ++depth_;
    for (const std::size_t index : lists_[position - 1]) {
        const Receiver& receiver = receivers_[index];
        receiver.call(receiver.target, frame);
    }
    --depth_;
}

} // namespace eposp::canopen
