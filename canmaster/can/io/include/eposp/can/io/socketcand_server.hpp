#pragma once

#include "eposp/can/virtual_bus.hpp"
#include "eposp/core/result.hpp"
#include "eposp/core/time.hpp"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eposp::can::io {

/// What a server allows its clients; the options a host gives its users.
struct SocketcandLimits {
    /// Frames each client's port holds for the bus: a client sends in bursts, as a gateway
    /// does. A frame sent while it is full is dropped (the port's tx-overflows), and the client
    /// is told once per burst with `< error ... >`.
    std::size_t tx_queue_capacity = kGatewayTxQueueCapacity;
    /// Connections at once, those still without `< open >` included, so that idle connections
    /// cannot use up the process's file descriptors. One more is answered `< error ... >` and
    /// closed at once.
    std::size_t max_clients = 64;
    /// A connection that has not opened the bus this long after connecting is closed.
    core::Duration open_timeout = std::chrono::seconds(5);
};

struct SocketcandServerConfig {
    /// HOST:PORT to listen on, or PORT alone for 127.0.0.1; IPv6 hosts in brackets. Port 0
    /// picks a free port (SocketcandServer::port() tells which). 29536 is socketcand's own.
    std::string listen = "127.0.0.1:29536";
    /// Frames are stamped with the loop time plus this offset. 0 in a virtual run; a real-time
    /// run passes the wall clock's epoch (TraceClock::aligned(...).epoch_offset()), so clients
    /// see Unix times as from socketcand itself.
    core::Duration epoch_offset{};
    /// A client whose unsent output grows beyond this stops receiving from the bus: frames then
    /// wait in its port's receive queue, and beyond that queue's capacity count as receive
    /// overflows. It resumes once its output has drained below `resume_below_bytes`.
    std::size_t pause_above_bytes = 64 * 1024;
    std::size_t resume_below_bytes = 16 * 1024;
    /// A client that lets this much pile up (it reads nothing, even replies) is disconnected.
    std::size_t disconnect_above_bytes = 1024 * 1024;
    /// The kernel's send buffer for each client. Left to itself, Linux lets it grow to
    /// megabytes: a client that falls behind would get frames seconds late instead of losing
    /// them visibly to receive overflows. 64 KiB hold about 1500 frames.
    int socket_send_buffer_bytes = 64 * 1024;
    SocketcandLimits limits = {};
};

/// A client joining or leaving, for the host to report.
struct SocketcandClientEvent {
    enum class Kind {
        Joined,  ///< it opened the bus, and has a port on it
        Left,    ///< a client that had joined went away
        Dropped, ///< a connection ended without joining: no or a wrong `< open >`, too many
                 ///< clients, ...
    };
    Kind kind = Kind::Joined;
    std::string client; ///< its port's name on the bus, e.g. "socketcand-1"; empty when Dropped
    std::string remote; ///< its TCP address, e.g. "127.0.0.1:50412"
    std::string reason; ///< why it left or was dropped
};

/// What the server has seen since it opened.
struct SocketcandServerStatistics {
    std::uint64_t joined = 0;      ///< clients that opened the bus
    std::uint64_t dropped = 0;     ///< connections that ended without opening it
    std::uint64_t turned_away = 0; ///< of those, refused at once because of max_clients
    /// The ports of the clients that have left, summed: their ports are gone from the bus, what
    /// they carried and lost is not.
    std::uint64_t left = 0;
    std::uint64_t left_tx_frames = 0;
    std::uint64_t left_rx_frames = 0;
    std::uint64_t left_tx_overflows = 0; ///< frames they sent that a full queue dropped
    std::uint64_t left_rx_overflows = 0;
};

/// A connected client as the host sees it.
struct SocketcandClientInfo {
    std::string client; ///< its port's name on the bus, e.g. "socketcand-1"
    std::string remote; ///< its TCP address
    /// Its port's counters (receive overflows tell that it did not keep up); nothing before it
    /// has opened the bus.
    std::optional<PortStatistics> port;
};

/// A TCP server speaking the socketcand protocol (linux-can/socketcand, doc/protocol.md) in
/// raw mode, so that independent tools (python-can's `socketcand` interface, Kayak, ...) join a
/// VirtualBus without kernel CAN. Every client that opens the bus by its name becomes a port of
/// the bus: the frames it sends go on the bus, every frame the bus carries is sent to it as
/// `< frame ... >`. Runs on the loop's io_context, without threads.
class SocketcandServer {
public:
    using EventHandler = std::function<void(const SocketcandClientEvent&)>;

    /// Starts listening, or says why it cannot (bad address, address in use, a limit of 0,
    /// ...). The bus and its loop must outlive the server.
    static core::Result<std::unique_ptr<SocketcandServer>> open(VirtualBus& bus,
                                                                SocketcandServerConfig config = {});

    /// Disconnects every client and stops listening.
    ~SocketcandServer();
    SocketcandServer(const SocketcandServer&) = delete;
    SocketcandServer& operator=(const SocketcandServer&) = delete;

    /// The port listened on: the one asked for, or the one picked for port 0.
    std::uint16_t port() const;
    /// HOST:PORT listened on, e.g. "127.0.0.1:29536".
    std::string address() const;
    /// Connections open now, those that have not opened the bus yet included.
    std::size_t client_count() const;
    std::vector<SocketcandClientInfo> clients() const;
    SocketcandServerStatistics statistics() const;
    void on_client_event(EventHandler handler);

private:
    class Impl;
    explicit SocketcandServer(std::shared_ptr<Impl> impl);

    std::shared_ptr<Impl> impl_;
};

} // namespace eposp::can::io
