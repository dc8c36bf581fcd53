#include "eposp/service/paced_link.hpp"

#include "line_queue.hpp"

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
    : line_(std::move(line)), pacing_(pacing),
      outgoing_(std::make_unique<LineQueue>(
          loop, pacing_, [this](std::span<const std::uint8_t> bytes) { line_->send(bytes); })),
      incoming_(std::make_unique<LineQueue>(
          loop, pacing_, [this](std::span<const std::uint8_t> bytes) { deliver(bytes); })) {
    line_->on_receive([this](std::span<const std::uint8_t> bytes) {
        if (!pacing_.enabled) {
            deliver(bytes);
            return;
        }
        dropped_full_ += incoming_->push(bytes);
    });
    line_->on_event([this](const LinkEvent& event) {
        // Meant for, or sent by, the host that left.
        dropped_no_host_ += outgoing_->clear();
        incoming_->clear();
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
    dropped_full_ += outgoing_->push(bytes);
}

std::size_t PacedLink::queued_bytes() const {
    return outgoing_->queued();
}

LinkStatistics PacedLink::statistics() const {
    LinkStatistics statistics = line_->statistics();
    statistics.bytes_dropped_full += dropped_full_;
    statistics.bytes_dropped_no_host += dropped_no_host_;
    return statistics;
}

} // namespace eposp::service
