#include "eposp/can/io/socketcand_client_port.hpp"

#include "eposp/can/io/socketcand_protocol.hpp"
#include "eposp/core/tcp_address.hpp"
#include "outgoing_bytes.hpp"

#include <array>
#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <chrono>
#include <fmt/format.h>
#include <utility>
#include <variant>

namespace eposp::can::io {

namespace sc = socketcand;
using boost::asio::ip::tcp;

namespace {

/// Frames waiting for a server that does not read (or for the handshake) are refused beyond
/// this, as a controller refuses frames when its transmit queue is full: about 1500 frames.
constexpr std::size_t kMaxUnsentBytes = 64 * 1024;
/// A server that accepts but never completes the handshake (or a host that never answers the
/// connect) must not hold a process that waits for raw mode forever.
constexpr auto kHandshakeTimeout = std::chrono::seconds(10);

} // namespace

/// The socket and the protocol state. Shared with the pending connect, reads and writes, so
/// that a completion arriving after the port is gone finds a detached connection instead of a
/// destroyed port.
class SocketcandClientPort::Connection : public std::enable_shared_from_this<Connection> {
public:
    Connection(core::EventLoop& loop, std::string address, std::string bus)
        : loop_(loop), socket_(loop.io()), address_(std::move(address)), bus_(std::move(bus)) {}

    void start(const tcp::resolver::results_type& endpoints) {
        handshake_timer_ = core::ScopedTimer(loop_, loop_.after(kHandshakeTimeout, [this] {
            fail(fmt::format("no socketcand handshake from {} within {} s", address_,
                             kHandshakeTimeout.count()));
        }));
        boost::asio::async_connect(
            socket_, endpoints,
            [self = shared_from_this()](boost::system::error_code error, const tcp::endpoint&) {
                self->on_connected(error);
            });
    }

    void attach(SocketcandClientPort& port) { port_ = &port; }
    void detach() {
        port_ = nullptr;
        handler_ = nullptr;
        close();
    }

    SendStatus send(const Frame& frame);
    bool connected() const { return state_ == State::Raw; }
    const std::string& failure() const { return failure_; }
    void on_event(EventHandler handler) { handler_ = std::move(handler); }

private:
    enum class State { Connecting, AwaitHi, AwaitOpen, AwaitRaw, Raw, Failed };

    void on_connected(boost::system::error_code error);
    void read();
    void on_read(boost::system::error_code error, std::size_t size);
    void process_input();

    void handle(const sc::Hi&);
    void handle(const sc::Ok&);
    void handle(const sc::Echo&) {} // we send no echo; a stray one harms nothing
    void handle(const sc::ReceivedFrame& received);
    void handle(const sc::ErrorReply& reply);
    void handle(const sc::Unknown&) {} // e.g. `fdframe`, which a classic CAN port cannot take
    void handle(const sc::Malformed& malformed);

    void enqueue(std::string_view message);
    void flush();
    void on_written(boost::system::error_code error);
    std::size_t unsent_bytes() const { return held_.size() + outgoing_.size(); }

    void report(Event::Kind kind, std::string text);
    void fail(std::string reason);
    void close();

    core::EventLoop& loop_;
    tcp::socket socket_;
    std::string address_;
    std::string bus_;
    SocketcandClientPort* port_ = nullptr;
    EventHandler handler_;
    core::ScopedTimer handshake_timer_;

    State state_ = State::Connecting;
    std::string failure_;
    std::array<char, 4096> read_buffer_{};
    std::string input_;
    std::string held_; ///< frames sent before raw mode is on
    OutgoingBytes outgoing_;
};

// ---- Connecting and the handshake -------------------------------------------------------------

void SocketcandClientPort::Connection::on_connected(boost::system::error_code error) {
    if (state_ != State::Connecting) {
        return; // failed (timed out) or detached meanwhile
    }
    if (error) {
        fail(fmt::format("cannot connect to {}: {}", address_, error.message()));
        return;
    }
    // Each frame goes out as soon as it is sent, like on a bus; a socket that refuses the option
    // only adds latency.
    boost::system::error_code ignored;
    socket_.set_option(tcp::no_delay(true), ignored);
    state_ = State::AwaitHi;
    read();
}

void SocketcandClientPort::Connection::handle(const sc::Hi&) {
    if (state_ != State::AwaitHi) {
        fail(fmt::format("{} sent < hi > out of turn", address_));
        return;
    }
    state_ = State::AwaitOpen;
    enqueue(fmt::format("< open {} >", bus_));
}

void SocketcandClientPort::Connection::handle(const sc::Ok&) {
    if (state_ == State::AwaitOpen) {
        state_ = State::AwaitRaw;
        enqueue("< rawmode >");
        return;
    }
    if (state_ != State::AwaitRaw) {
        fail(fmt::format("{} sent < ok > out of turn", address_));
        return;
    }
    state_ = State::Raw;
    handshake_timer_.cancel();
    enqueue(std::exchange(held_, {}));
    report(Event::Kind::Connected, fmt::format("bus {} on {} in raw mode", bus_, address_));
}

void SocketcandClientPort::Connection::handle(const sc::ErrorReply& reply) {
    switch (state_) {
    case State::Raw: // a refused frame (socketcand has no sendrtr, ...): the link stays
        report(Event::Kind::ServerError, fmt::format("{} answered: {}", address_, reply.reason));
        return;
    case State::AwaitOpen:
        fail(fmt::format("{} refused to open bus {}: {}", address_, bus_, reply.reason));
        return;
    case State::AwaitRaw:
        fail(fmt::format("{} refused raw mode on bus {}: {}", address_, bus_, reply.reason));
        return;
    default:
        fail(fmt::format("{} refused the connection: {}", address_, reply.reason));
        return;
    }
}

void SocketcandClientPort::Connection::handle(const sc::Malformed& malformed) {
    fail(fmt::format("{} sent a malformed message ({})", address_, malformed.reason));
}

// ---- Reading ----------------------------------------------------------------------------------

void SocketcandClientPort::Connection::read() {
    socket_.async_read_some(
        boost::asio::buffer(read_buffer_),
        [self = shared_from_this()](boost::system::error_code error, std::size_t size) {
            self->on_read(error, size);
        });
}

void SocketcandClientPort::Connection::on_read(boost::system::error_code error, std::size_t size) {
    if (state_ == State::Failed) {
        return;
    }
    if (error) {
        fail(error == boost::asio::error::eof
                 ? fmt::format("{} closed the connection", address_)
                 : fmt::format("reading from {} failed: {}", address_, error.message()));
        return;
    }
    input_.append(read_buffer_.data(), size);
    process_input();
    if (state_ != State::Failed) {
        read();
    }
}

void SocketcandClientPort::Connection::process_input() {
    while (state_ != State::Failed) {
        const sc::Scan scan = sc::scan_message(input_);
        switch (scan.kind) {
        case sc::Scan::Kind::Message: {
            const sc::ServerMessage message = sc::parse_server_message(scan.message);
            input_.erase(0, scan.consumed);
            std::visit([this](const auto& m) { handle(m); }, message);
            break;
        }
        case sc::Scan::Kind::Incomplete:
            input_.erase(0, scan.consumed);
            return;
        case sc::Scan::Kind::Garbage:
            fail(fmt::format("{} sent bytes outside a < > message", address_));
            return;
        case sc::Scan::Kind::TooLong:
            fail(fmt::format("{} sent a message longer than {} bytes", address_,
                             sc::kMaxMessageLength));
            return;
        }
    }
}

void SocketcandClientPort::Connection::handle(const sc::ReceivedFrame& received) {
    // Frames before raw mode cannot come from a socketcand server; error frames: see the header.
    if (state_ == State::Raw && port_ && !received.frame.error) {
        port_->deliver(received.frame); // may destroy the port, which detaches us
    }
}

// ---- Writing ----------------------------------------------------------------------------------

SendStatus SocketcandClientPort::Connection::send(const Frame& frame) {
    if (!frame.valid()) {
        return SendStatus::InvalidFrame;
    }
    if (state_ == State::Failed) {
        return SendStatus::Disconnected;
    }
    if (unsent_bytes() > kMaxUnsentBytes) {
        return SendStatus::TxOverflow;
    }
    const std::string message = sc::format_send(frame);
    if (state_ == State::Raw) {
        enqueue(message);
    } else {
        held_ += message;
    }
    return SendStatus::Queued;
}

void SocketcandClientPort::Connection::enqueue(std::string_view message) {
    outgoing_.append(message);
    flush();
}

void SocketcandClientPort::Connection::flush() {
    if (state_ == State::Failed) {
        return;
    }
    outgoing_.write_next(socket_, [self = shared_from_this()](boost::system::error_code error) {
        self->on_written(error);
    });
}

void SocketcandClientPort::Connection::on_written(boost::system::error_code error) {
    outgoing_.written();
    if (state_ == State::Failed) {
        return;
    }
    if (error) {
        fail(fmt::format("writing to {} failed: {}", address_, error.message()));
        return;
    }
    flush();
}

// ---- Reporting and closing --------------------------------------------------------------------

void SocketcandClientPort::Connection::report(Event::Kind kind, std::string text) {
    if (handler_) {
        const auto keep = shared_from_this(); // the handler may destroy the port
        const EventHandler handler = handler_;
        handler(Event{kind, std::move(text)});
    }
}

void SocketcandClientPort::Connection::fail(std::string reason) {
    if (state_ == State::Failed) {
        return;
    }
    failure_ = reason;
    close();
    report(Event::Kind::Failed, std::move(reason));
}

void SocketcandClientPort::Connection::close() {
    state_ = State::Failed;
    handshake_timer_.cancel();
    held_.clear();
    outgoing_.drop_pending();
    boost::system::error_code ignored; // the peer may already be gone; nothing to do about it
    socket_.shutdown(tcp::socket::shutdown_both, ignored);
    socket_.close(ignored);
}

// ---- The port ---------------------------------------------------------------------------------

core::Result<std::unique_ptr<SocketcandClientPort>>
SocketcandClientPort::open(core::EventLoop& loop, const std::string& address,
                           const std::string& bus_name) {
    const auto parsed = core::parse_tcp_address(address);
    if (!parsed) {
        return core::Error{
            fmt::format("'{}' is not an address to connect to (HOST:PORT)", address)};
    }
    const bool bus_name_ok = !bus_name.empty() && bus_name.size() <= sc::kMaxBusNameLength &&
                             bus_name.find_first_of(" \t\r\n<>") == std::string::npos;
    if (!bus_name_ok) {
        return core::Error{
            fmt::format("'{}' is not a socketcand bus name (1 to {} characters, no spaces or < >)",
                        bus_name, sc::kMaxBusNameLength)};
    }
    boost::system::error_code error;
    const auto endpoints = tcp::resolver(loop.io()).resolve(
        parsed->host, std::to_string(parsed->port), tcp::resolver::numeric_service, error);
    if (error || endpoints.empty()) {
        return core::Error{fmt::format("cannot resolve {}: {}", parsed->host, error.message())};
    }
    auto connection = std::make_shared<Connection>(loop, address, bus_name);
    std::unique_ptr<SocketcandClientPort> port(
        new SocketcandClientPort(fmt::format("{} {}", address, bus_name), connection));
    connection->attach(*port);
    connection->start(endpoints);
    return port;
}

SocketcandClientPort::SocketcandClientPort(std::string name, std::shared_ptr<Connection> connection)
    : name_(std::move(name)), connection_(std::move(connection)) {}

SocketcandClientPort::~SocketcandClientPort() {
    connection_->detach();
}

SendStatus SocketcandClientPort::send(const Frame& frame) {
    return connection_->send(frame);
}

bool SocketcandClientPort::connected() const {
    return connection_->connected();
}

const std::string& SocketcandClientPort::failure() const {
    return connection_->failure();
}

void SocketcandClientPort::on_event(EventHandler handler) {
    connection_->on_event(std::move(handler));
}

} // namespace eposp::can::io
