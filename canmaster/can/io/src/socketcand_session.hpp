#pragma once

// Internal to the socketcand server: one client connection and its protocol state.

#include "eposp/can/io/socketcand_protocol.hpp"
#include "eposp/can/io/socketcand_server.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/core/event_loop.hpp"
#include "outgoing_bytes.hpp"

#include <array>
#include <boost/asio/ip/tcp.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::can::io {

/// One client: greets it, runs the protocol's modes (NO_BUS, then BCM after `open`, RAW after
/// `rawmode`), holds its port on the bus while a bus is open, and forwards the bus's frames in
/// raw mode. Shared with its pending reads and writes, so that a completion arriving after the
/// server dropped the session finds it closed rather than destroyed.
class SocketcandSession : public std::enable_shared_from_this<SocketcandSession> {
public:
    using JoinedHandler = std::function<void(SocketcandSession&)>;
    using ClosedHandler = std::function<void(SocketcandSession&, const std::string& reason)>;

    SocketcandSession(boost::asio::ip::tcp::socket socket, std::string name, VirtualBus& bus,
                      const SocketcandServerConfig& config, JoinedHandler on_joined,
                      ClosedHandler on_closed);

    /// Greets the client, starts reading and gives it SocketcandLimits::open_timeout to open
    /// the bus.
    void start();
    /// Closes at once without reporting back: the server is going away.
    void abort();

    const std::string& name() const { return name_; }
    const std::string& remote() const { return remote_; }
    /// Whether it has opened the bus (and so had a port on it).
    bool joined() const { return last_port_statistics_.has_value(); }
    /// Its port's counters, the last ones once the port is gone.
    SocketcandClientInfo info() const;

private:
    enum class State { NoBus, Bcm, Raw, Closing, Closed };

    void read();
    void on_read(boost::system::error_code error, std::size_t size);
    void process_input();

    void handle(const socketcand::OpenBus& open);
    void handle(const socketcand::SwitchMode& mode);
    void handle(const socketcand::Echo& echo);
    void handle(const socketcand::SendFrame& send);
    void handle(const socketcand::NotSupported& command);
    void handle(const socketcand::Unknown& command);
    void handle(const socketcand::Malformed& command);

    void on_bus_frame(const Frame& frame);
    /// The client has hung up: closes once the frames it sent have left its port's queue.
    void close_when_sent();
    /// Frames the client sent that its port still holds.
    std::uint64_t frames_waiting() const;
    /// Detaches the port from the bus, keeping its last counters.
    void release_port();
    void reply_error(std::string_view reason);
    void enqueue(std::string_view message);
    void flush();
    void on_written(boost::system::error_code error);
    std::size_t unsent_bytes() const { return outgoing_.size(); }
    void resume_if_drained();

    /// Says why in an error message, then closes once it is sent.
    void close_after_reply(std::string_view reply, std::string reason);
    /// Closes later, outside whatever callback is running (a port must not be destroyed from
    /// within its own receive handler).
    void close_soon(std::string reason);
    void close(const std::string& reason);

    boost::asio::ip::tcp::socket socket_;
    std::string name_;
    std::string remote_;
    VirtualBus& bus_;
    SocketcandServerConfig config_;
    JoinedHandler on_joined_;
    ClosedHandler on_closed_;

    State state_ = State::NoBus;
    core::ScopedTimer open_deadline_;
    std::unique_ptr<VirtualPort> port_;
    std::optional<PortStatistics> last_port_statistics_;
    /// Why the last frame the client sent was refused, until one is queued again: the client
    /// is told once per burst of refusals, not once per frame.
    std::optional<SendStatus> refusing_;
    std::uint64_t frames_queued_ = 0;
    std::optional<VirtualBus::ObserverId> drain_observer_;
    core::ScopedTimer drain_deadline_;
    bool receive_paused_ = false;
    /// Frames of the first moments of raw mode, sent once the client has read its `< ok >`.
    std::string held_frames_;
    core::ScopedTimer settle_;
    std::string close_reason_;

    std::array<char, 4096> read_buffer_{};
    std::string input_;
    OutgoingBytes outgoing_;
};

} // namespace eposp::can::io
