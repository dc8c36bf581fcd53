#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/service/link.hpp"

#include <memory>
#include <string>

namespace eposp::service {

/// The client side of a link over TCP: how `eposp download` / `od` reach a `eposp serve
/// --serial tcp:ADDR`. Connecting is asynchronous; bytes sent meanwhile wait and go out once
/// connected. A refused connection, or the server closing it, closes the link (Closed).
class TcpClientLink final : public Link {
public:
    /// Starts connecting to `address` ("HOST:PORT", "[IPV6]:PORT", or "PORT" for 127.0.0.1),
    /// or says why it cannot (malformed, does not resolve).
    static core::Result<std::unique_ptr<TcpClientLink>>
    open(core::EventLoop& loop, const std::string& address,
         std::size_t max_unsent_bytes = kDefaultMaxUnsentBytes);
    ~TcpClientLink() override;
    TcpClientLink(const TcpClientLink&) = delete;
    TcpClientLink& operator=(const TcpClientLink&) = delete;

    void send(std::span<const std::uint8_t> bytes) override;
    /// "tcp 127.0.0.1:4001" as given.
    std::string_view name() const override { return name_; }
    LinkStatistics statistics() const override;
    bool connected() const;

private:
    class Impl;
    explicit TcpClientLink(std::string name, std::shared_ptr<Impl> impl);

    std::string name_;
    std::shared_ptr<Impl> impl_;
};

} // namespace eposp::service
