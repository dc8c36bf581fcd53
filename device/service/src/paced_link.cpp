#include "eposp/service/paced_link.hpp"

#include <algorithm>

namespace eposp::service {
namespace {

constexpr std::uint64_t kNanosecondsPerSecond = 1'000'000'000;

} // namespace

core::Duration LinkPacing::time_for(std::uint64_t bytes) const {
    // Rounded up to whole nanoseconds: a byte never leaves before its last bit.
    const std::uint64_t line_ns = bytes * bits_per_byte * kNanosecondsPerSecond;
    return core::Duration((line_ns + bits_per_second - 1) / bits_per_second);
}

core::Result<std::unique_ptr<PacedLink>>
PacedLink::wrap(core::EventLoop& loop, std::unique_ptr<Link> line, LinkPacing pacing) {
    if (pacing.enabled && (pacing.bits_per_second == 0 || pacing.bits_per_byte == 0)) {
        return core::Error{"a paced link needs a line rate above 0 bit/s and bytes of 1 bit or "
                           "more"};
    }
    return std::unique_ptr<PacedLink>(new PacedLink(loop, std::move(line), pacing));
}

PacedLink::PacedLink(core::EventLoop& loop, std::unique_ptr<Link> line, LinkPacing pacing)
    : loop_(loop), line_(std::move(line)), pacing_(pacing) {
    line_->on_receive([this](std::span<const std::uint8_t> bytes) { deliver(bytes); });
    line_->on_event([this](const LinkEvent& event) {
        forget_queue(); // meant for the host that left
        report(event);
    });
}

PacedLink::~PacedLink() {
    line_->on_receive(nullptr);
    line_->on_event(nullptr);
}

void PacedLink::send(std::span<const std::uint8_t> bytes) {
    if (!pacing_.enabled) {
        line_->send(bytes);
        return;
    }
    if (closed()) {
        dropped_no_host_ += bytes.size();
        return;
    }
    if (queued_bytes() == 0) {
        // The line is idle: every byte handed over has left by now (see drain()).
        queue_.clear();
        head_ = 0;
        burst_start_ = loop_.now();
        burst_sent_ = 0;
    }
    const std::size_t room =
        pacing_.max_queued_bytes - std::min(pacing_.max_queued_bytes, queued_bytes());
    const std::size_t taken = std::min(room, bytes.size());
    queue_.append(reinterpret_cast<const char*>(bytes.data()), taken);
    dropped_full_ += bytes.size() - taken;
    schedule();
}

core::TimePoint PacedLink::end_of(std::uint64_t index) const {
    return burst_start_ + pacing_.time_for(index + 1);
}

void PacedLink::schedule() {
    if (queued_bytes() == 0 || timer_.pending()) {
        return; // a pending drain is never later than what more bytes would ask for
    }
    const core::TimePoint next = end_of(burst_sent_);
    const core::TimePoint last = end_of(burst_sent_ + queued_bytes() - 1);
    const core::TimePoint when = std::min(std::max(next, loop_.now() + pacing_.batch), last);
    timer_ = core::ScopedTimer(loop_, loop_.at(when, [this] { drain(); }));
}

void PacedLink::drain() {
    timer_ = core::ScopedTimer(); // this one has run: schedule() may set the next
    if (queued_bytes() == 0) {
        return;
    }
    // Bytes of the burst whose last bit has arrived: byte k ends at ceil((k+1)·T), so k+1 ≤
    // floor(elapsed / T) with T the byte time, exactly as end_of() computes it.
    // Clamped to the burst's end, so that a loop that woke up late cannot overflow the product.
    const core::TimePoint now = std::min(loop_.now(), end_of(burst_sent_ + queued_bytes() - 1));
    const auto elapsed = static_cast<std::uint64_t>((now - burst_start_).count());
    const std::uint64_t done = elapsed * pacing_.bits_per_second /
                               (std::uint64_t{pacing_.bits_per_byte} * kNanosecondsPerSecond);
    const std::size_t count = static_cast<std::size_t>(done - burst_sent_);
    if (count > 0) {
        const std::span<const std::uint8_t> due(
            reinterpret_cast<const std::uint8_t*>(queue_.data()) + head_, count);
        head_ += count;
        burst_sent_ += count;
        line_->send(due);
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
    }
    schedule();
}

void PacedLink::forget_queue() {
    dropped_no_host_ += queued_bytes();
    queue_.clear();
    head_ = 0;
    timer_.cancel();
}

LinkStatistics PacedLink::statistics() const {
    LinkStatistics statistics = line_->statistics();
    statistics.bytes_dropped_full += dropped_full_;
    statistics.bytes_dropped_no_host += dropped_no_host_;
    return statistics;
}

} // namespace eposp::service
