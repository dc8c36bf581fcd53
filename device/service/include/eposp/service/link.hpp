#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

namespace eposp::service {

/// What a link holds for a host that does not read before it drops (LinkStatistics::
/// bytes_dropped_full): 64 KiB, several seconds of output at 115200 baud.
inline constexpr std::size_t kDefaultMaxUnsentBytes = 64 * 1024;

/// Something a link tells beyond bytes (docs/service-interface.md, "The links").
struct LinkEvent {
    enum class Kind {
        /// The host went away (closed the pseudo-terminal, the TCP connection). Bytes still
        /// queued for it are dropped; the link serves the next host.
        HungUp,
        /// The link is gone for good: the device at the other end vanished, a connection
        /// failed. send() drops from now on.
        Closed,
    };
    Kind kind = Kind::HungUp;
    std::string text; ///< what happened, in words for the user
};

/// What a link has carried and lost since it opened.
struct LinkStatistics {
    std::uint64_t bytes_sent = 0;     ///< handed to the host (the kernel has them)
    std::uint64_t bytes_received = 0; ///< handed on to the receive handler
    /// Bytes sent while the output queue was full (a host that does not read): the newest are
    /// dropped, what is queued stays whole.
    std::uint64_t bytes_dropped_full = 0;
    /// Bytes sent while no host was there, or still queued when it hung up.
    std::uint64_t bytes_dropped_no_host = 0;
    std::uint64_t hang_ups = 0;
    std::uint64_t hosts_turned_away = 0; ///< TCP: connections closed because a host was served
};

/// A byte link between the device (or a client) and one host: a pseudo-terminal, a serial
/// device, a TCP connection, or a pacing layer over one of them. Runs on the event loop's
/// io_context without threads; send() never blocks and never fails loudly: what cannot be sent
/// is counted in statistics(), what ends the link is reported as a LinkEvent.
///
/// The handlers run from the loop; they must not destroy the link (post that instead).
class Link {
public:
    using ReceiveHandler = std::function<void(std::span<const std::uint8_t>)>;
    using EventHandler = std::function<void(const LinkEvent&)>;

    virtual ~Link() = default;

    /// Queues `bytes` for the host.
    virtual void send(std::span<const std::uint8_t> bytes) = 0;
    /// For messages: "pty /dev/pts/4", "tcp 127.0.0.1:4001", "/dev/ttyUSB0".
    virtual std::string_view name() const = 0;
    virtual LinkStatistics statistics() const { return statistics_; }
    /// True once a Closed event was reported.
    bool closed() const { return closed_; }

    /// Bytes as they arrive, in order, in pieces of any size.
    void on_receive(ReceiveHandler handler) { receive_handler_ = std::move(handler); }
    void on_event(EventHandler handler) { event_handler_ = std::move(handler); }

protected:
    /// Counts the bytes and hands them to the receive handler.
    void deliver(std::span<const std::uint8_t> bytes);
    /// Counts a hang-up, marks the link closed on Closed, and tells the event handler.
    void report(LinkEvent event);

    LinkStatistics statistics_;

private:
    ReceiveHandler receive_handler_;
    EventHandler event_handler_;
    bool closed_ = false;
};

} // namespace eposp::service
