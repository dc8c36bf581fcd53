#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/service/link.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

namespace eposp::service {

/// The line rate an emulated link sends at (docs/service-interface.md, "Pacing").
struct LinkPacing {
    bool enabled = true;
    std::uint32_t bits_per_second = 115200;
    /// Bits on the line per byte: 10 for 8N1 (start bit, 8 data bits, stop bit).
    std::uint32_t bits_per_byte = 10;
    /// Bytes that are due within this much of each other are handed to the line together, as
    /// a UART driver or a USB frame (1 ms) does, so that a real-time loop wakes up at most once
    /// a millisecond; the last byte of a burst always leaves exactly when it is due.
    core::Duration batch = std::chrono::milliseconds(1);
    /// Bytes waiting for the line beyond this are dropped, the newest first.
    std::size_t max_queued_bytes = kDefaultMaxUnsentBytes;

    /// RS-232, 8N1 (issue 14: 115200 baud by default).
    static LinkPacing rs232(std::uint32_t baud = 115200) { return {.bits_per_second = baud}; }
    /// USB: 1 Mbit/s (issue 14), counted with the 10 bits a byte of a UART line like RS-232.
    static LinkPacing usb() { return {.bits_per_second = 1'000'000}; }
    /// Everything is handed to the line at once (`--no-pacing`).
    static LinkPacing off() { return {.enabled = false}; }

    /// How long `bytes` take on the line.
    core::Duration time_for(std::uint64_t bytes) const;
};

class LineQueue;

/// Paces another link at a line rate in both directions, on the loop: byte queues drained by
/// loop timers, never a sleep, so that a virtual run shows the timings of the real line. Each
/// byte is handed over when its last bit would have crossed the line: what is sent reaches the
/// host so, and what the host sends reaches the device so, however fast the pseudo-terminal or
/// socket carried it (1152 bytes at 115200 baud take 100 ms either way). A hang-up drops what
/// still waits, both ways.
class PacedLink final : public Link {
public:
    /// Takes `line` over; a rate of 0 or a byte of 0 bits is refused.
    static core::Result<std::unique_ptr<PacedLink>>
    wrap(core::EventLoop& loop, std::unique_ptr<Link> line, LinkPacing pacing);
    ~PacedLink() override;
    PacedLink(const PacedLink&) = delete;
    PacedLink& operator=(const PacedLink&) = delete;

    void send(std::span<const std::uint8_t> bytes) override;
    std::string_view name() const override { return line_->name(); }
    /// The line's, plus what the pacing queues dropped.
    LinkStatistics statistics() const override;

    const LinkPacing& pacing() const { return pacing_; }
    /// Bytes waiting for the line, to the host.
    std::size_t queued_bytes() const;
    Link& line() { return *line_; }

private:
    PacedLink(core::EventLoop& loop, std::unique_ptr<Link> line, LinkPacing pacing);

    std::unique_ptr<Link> line_;
    LinkPacing pacing_;
    std::unique_ptr<LineQueue> outgoing_; ///< to the host
    std::unique_ptr<LineQueue> incoming_; ///< from the host
    std::uint64_t dropped_full_ = 0;
    std::uint64_t dropped_no_host_ = 0;
};

} // namespace eposp::service
