#include "line_queue.hpp"

#include <algorithm>

namespace eposp::service {
namespace {

constexpr std::uint64_t kNanosecondsPerSecond = 1'000'000'000;

} // namespace

LineQueue::LineQueue(core::EventLoop& loop, const LinkPacing& pacing, Sink sink)
    : loop_(loop), pacing_(pacing), sink_(std::move(sink)) {}

std::size_t LineQueue::push(std::span<const std::uint8_t> bytes) {
    if (queued() == 0) {
        // The line is idle: every byte handed over has crossed it by now (see drain()).
        queue_.clear();
        head_ = 0;
        burst_start_ = loop_.now();
        burst_sent_ = 0;
    }
    const std::size_t room =
        pacing_.max_queued_bytes - std::min(pacing_.max_queued_bytes, queued());
    const std::size_t taken = std::min(room, bytes.size());
    queue_.append(reinterpret_cast<const char*>(bytes.data()), taken);
    schedule();
    return bytes.size() - taken;
}

std::size_t LineQueue::clear() {
    const std::size_t forgotten = queued();
    queue_.clear();
    head_ = 0;
    timer_.cancel();
    return forgotten;
}

core::TimePoint LineQueue::end_of(std::uint64_t index) const {
    return burst_start_ + pacing_.time_for(index + 1);
}

void LineQueue::schedule() {
    if (queued() == 0 || timer_.pending()) {
        return; // a pending drain is never later than what more bytes would ask for
    }
    const core::TimePoint next = end_of(burst_sent_);
    const core::TimePoint last = end_of(burst_sent_ + queued() - 1);
    const core::TimePoint when = std::min(std::max(next, loop_.now() + pacing_.batch), last);
    timer_ = core::ScopedTimer(loop_, loop_.at(when, [this] { drain(); }));
}

void LineQueue::drain() {
    timer_ = core::ScopedTimer(); // this one has run: schedule() may set the next
    if (queued() == 0) {
        return;
    }
    // Bytes of the burst whose last bit has arrived: byte k ends at ceil((k+1)·T), so k+1 ≤
    // floor(elapsed / T) with T the byte time, exactly as end_of() computes it.
    // Clamped to the burst's end, so that a loop that woke up late cannot overflow the product.
    const core::TimePoint now = std::min(loop_.now(), end_of(burst_sent_ + queued() - 1));
    const auto elapsed = static_cast<std::uint64_t>((now - burst_start_).count());
    const std::uint64_t done = elapsed * pacing_.bits_per_second /
                               (std::uint64_t{pacing_.bits_per_byte} * kNanosecondsPerSecond);
    const std::size_t count = static_cast<std::size_t>(done - burst_sent_);
    if (count > 0) {
        // Copied out: the sink may queue more, which may move the queue's bytes.
        const std::string due = queue_.substr(head_, count);
        head_ += count;
        burst_sent_ += count;
        while (burst_sent_ >= pacing_.bits_per_second) {
            // bits_per_second bytes take exactly bits_per_byte seconds: moving the start on by
            // that keeps the arithmetic small during an endless burst, without rounding.
            burst_start_ += std::chrono::seconds(pacing_.bits_per_byte);
            burst_sent_ -= pacing_.bits_per_second;
        }
        if (head_ > queue_.size() / 2) {
            queue_.erase(0, head_); // keeps the queue from growing during a long burst
            head_ = 0;
        }
        sink_(std::span(reinterpret_cast<const std::uint8_t*>(due.data()), due.size()));
    }
    schedule();
}

} // namespace eposp::service
