#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/service/link.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace eposp::service {

struct TcpServerLinkOptions {
    std::size_t max_unsent_bytes = kDefaultMaxUnsentBytes;
};

/// The device side of a link over TCP (`--serial tcp:ADDR`): listens on ADDR and serves one
/// host at a time, as a serial port serves the one cable plugged into it.
///
/// A connection that arrives while a host is served is accepted and closed at once with nothing
/// sent (LinkStatistics::hosts_turned_away): queueing it would leave a second tool waiting
/// without a word, and two hosts must never interleave their frames. The host closing its
/// connection is a hang-up (HungUp); the next connection is served.
class TcpServerLink final : public Link {
public:
    /// Listens on `address`: "HOST:PORT", "[IPV6]:PORT", or "PORT" alone for 127.0.0.1; port 0
    /// picks a free port (port() tells which).
    static core::Result<std::unique_ptr<TcpServerLink>>
    open(core::EventLoop& loop, const std::string& address, TcpServerLinkOptions options = {});
    ~TcpServerLink() override;
    TcpServerLink(const TcpServerLink&) = delete;
    TcpServerLink& operator=(const TcpServerLink&) = delete;

    void send(std::span<const std::uint8_t> bytes) override;
    /// "tcp 127.0.0.1:4001".
    std::string_view name() const override { return name_; }
    LinkStatistics statistics() const override;

    std::uint16_t port() const;
    /// HOST:PORT listened on, e.g. "127.0.0.1:4001".
    std::string address() const;
    bool host_connected() const;

private:
    class Impl;
    explicit TcpServerLink(std::shared_ptr<Impl> impl);

    std::shared_ptr<Impl> impl_;
    std::string name_;
};

} // namespace eposp::service
