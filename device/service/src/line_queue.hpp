#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/service/paced_link.hpp"

#include <cstdint>
#include <functional>
#include <span>
#include <string>

namespace eposp::service {

/// One direction of a paced line: bytes queued now are handed to `sink` when their last bit
/// would have crossed the line (docs/service-interface.md, "Pacing"), by loop timers. Bytes
/// beyond the pacing's max_queued_bytes are dropped, the newest first.
class LineQueue {
public:
    using Sink = std::function<void(std::span<const std::uint8_t>)>;

    LineQueue(core::EventLoop& loop, const LinkPacing& pacing, Sink sink);

    /// Queues `bytes`; returns how many were dropped for want of room.
    std::size_t push(std::span<const std::uint8_t> bytes);
    /// Forgets what waits (a hang-up); returns how many bytes that was.
    std::size_t clear();
    std::size_t queued() const { return queue_.size() - head_; }

private:
    /// When byte `index` of the current burst has crossed the line.
    core::TimePoint end_of(std::uint64_t index) const;
    void schedule();
    void drain();

    core::EventLoop& loop_;
    const LinkPacing& pacing_;
    Sink sink_;
    std::string queue_;
    std::size_t head_ = 0; ///< bytes of queue_ already handed over
    core::TimePoint burst_start_{};
    std::uint64_t burst_sent_ = 0; ///< bytes of the current burst handed over
    core::ScopedTimer timer_;
};

} // namespace eposp::service
