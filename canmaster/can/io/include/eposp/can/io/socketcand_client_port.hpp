#pragma once

#include "eposp/can/port.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"

#include <functional>
#include <memory>
#include <string>

namespace eposp::can::io {

/// A bus that a socketcand server serves (socketcand itself, or SocketcandServer in another
/// process) as a Port: connects over TCP, greets the server as linux-can/socketcand expects
/// (`< hi >`; `< open BUS >` → `< ok >`; `< rawmode >` → `< ok >`), then sends each frame as
/// `< send ... >` and delivers each `< frame ... >` the server reports. Runs on the loop's
/// io_context, without threads (real-time pace).
///
/// Connecting is asynchronous: frames sent before raw mode wait and go out once it is on. A
/// failure (refused, `< error >` during the handshake, a malformed or over-long message, the
/// server closing) closes the connection for good: send() then says Disconnected and failure()
/// says why. Error frames on the server's bus are not delivered: socketcand reports only their
/// class, too little to follow the server's error state.
class SocketcandClientPort final : public Port {
public:
    struct Event {
        enum class Kind {
            Connected,   ///< raw mode is on; frames flow both ways
            ServerError, ///< an `< error >` in raw mode (e.g. a refused frame); the link stays
            Failed,      ///< the connection is gone; `text` says why
        };
        Kind kind = Kind::Connected;
        std::string text;
    };
    using EventHandler = std::function<void(const Event&)>;

    /// Starts connecting to `address` ("HOST:PORT", "[IPV6]:PORT", or "PORT" for 127.0.0.1)
    /// to open `bus_name`, or says why it cannot (a malformed address, a host that does not
    /// resolve, a bus name socketcand would refuse).
    static core::Result<std::unique_ptr<SocketcandClientPort>>
    open(core::EventLoop& loop, const std::string& address, const std::string& bus_name);

    ~SocketcandClientPort() override;
    SocketcandClientPort(const SocketcandClientPort&) = delete;
    SocketcandClientPort& operator=(const SocketcandClientPort&) = delete;

    /// Queued until the server has the frame (there is no acknowledgement); TxOverflow when the
    /// server does not read what it is sent; Disconnected once the connection failed.
    SendStatus send(const Frame& frame) override;
    ErrorState error_state() const override { return ErrorState::Active; }
    /// "HOST:PORT BUS" as given.
    std::string_view name() const override { return name_; }

    bool connected() const;
    /// Why the connection failed; empty while it is up or coming up.
    const std::string& failure() const;
    /// Told when raw mode is on, of `< error >` replies, and of the failure. The handler may
    /// destroy the port.
    void on_event(EventHandler handler);

private:
    class Connection;
    SocketcandClientPort(std::string name, std::shared_ptr<Connection> connection);

    std::string name_;
    std::shared_ptr<Connection> connection_;
};

} // namespace eposp::can::io
