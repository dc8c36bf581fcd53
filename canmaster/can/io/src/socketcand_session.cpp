#include "socketcand_session.hpp"

#include "eposp/core/tcp_address.hpp"

#include <boost/asio/post.hpp>
#include <boost/asio/write.hpp>
#include <fmt/format.h>
#include <utility>
#include <variant>

namespace eposp::can::io {

namespace sc = socketcand;

namespace {

/// Put before every frame forwarded in raw mode. python-can 4.1 drops the character after the
/// last complete message it parsed from a read; when the read ended inside the next message,
/// that character would be its '<' and the frame would be lost. A space between messages is
/// allowed by socketcand's framing and costs that client nothing.
constexpr std::string_view kFrameSeparator = " ";

/// python-can 4.1 reads each handshake reply with one recv() and wants exactly `< ok >` in it:
/// a frame sent right behind the reply to `< rawmode >` would land in the same read and fail
/// its handshake. Frames of this first moment of raw mode wait and follow it.
constexpr core::Duration kRawModeSettle = std::chrono::milliseconds(20);

/// How long the port of a client that has hung up may take to send what it had queued (1024
/// frames take 13 s at 10 kbit/s, 0.13 s at 1 Mbit/s).
constexpr core::Duration kLongestDrain = std::chrono::seconds(15);

constexpr std::string_view kClientDisconnected = "the client disconnected";

} // namespace

SocketcandSession::SocketcandSession(boost::asio::ip::tcp::socket socket, std::string name,
                                     VirtualBus& bus, const SocketcandServerConfig& config,
                                     JoinedHandler on_joined, ClosedHandler on_closed)
    : socket_(std::move(socket)), name_(std::move(name)), bus_(bus), config_(config),
      on_joined_(std::move(on_joined)), on_closed_(std::move(on_closed)) {
    boost::system::error_code error;
    const auto endpoint = socket_.remote_endpoint(error);
    remote_ = error ? std::string("unknown address") : core::format_endpoint(endpoint);
    // Tuning, which a socket that refuses it works without: each reply goes out as soon as it
    // is written (python-can reads the handshake replies one recv() each), and the kernel's
    // buffer stays small (see SocketcandServerConfig).
    socket_.set_option(boost::asio::ip::tcp::no_delay(true), error);
    socket_.set_option(boost::asio::socket_base::send_buffer_size(config_.socket_send_buffer_bytes),
                       error);
}

void SocketcandSession::start() {
    enqueue(sc::kHi);
    read();
    // An idle connection holds a file descriptor: one that does not open the bus is let go.
    const core::Duration timeout = config_.limits.open_timeout;
    open_deadline_ = core::ScopedTimer(bus_.loop(), bus_.loop().after(timeout, [this, timeout] {
        const std::string limit = core::format_duration(timeout);
        close_after_reply(sc::format_error(fmt::format("no bus opened within {}", limit)),
                          fmt::format("it did not open a bus within {}", limit));
    }));
}

void SocketcandSession::abort() {
    on_closed_ = nullptr;
    close("the server stopped");
}

SocketcandClientInfo SocketcandSession::info() const {
    return {name_, remote_, port_ ? std::optional(port_->statistics()) : last_port_statistics_};
}

// ---- Reading ----------------------------------------------------------------------------------

void SocketcandSession::read() {
    socket_.async_read_some(
        boost::asio::buffer(read_buffer_),
        [self = shared_from_this()](boost::system::error_code error, std::size_t size) {
            self->on_read(error, size);
        });
}

void SocketcandSession::on_read(boost::system::error_code error, std::size_t size) {
    if (state_ == State::Closed || state_ == State::Closing) {
        return;
    }
    if (error == boost::asio::error::eof) {
        close_when_sent();
        return;
    }
    if (error) {
        close(fmt::format("read failed: {}", error.message()));
        return;
    }
    input_.append(read_buffer_.data(), size);
    process_input();
    if (state_ != State::Closed && state_ != State::Closing) {
        read();
    }
}

void SocketcandSession::process_input() {
    while (state_ != State::Closed && state_ != State::Closing) {
        const sc::Scan scan = sc::scan_message(input_);
        switch (scan.kind) {
        case sc::Scan::Kind::Message:
            std::visit([this](const auto& command) { handle(command); },
                       sc::parse_command(scan.message));
            input_.erase(0, scan.consumed);
            break;
        case sc::Scan::Kind::Incomplete:
            input_.erase(0, scan.consumed);
            return;
        case sc::Scan::Kind::Garbage:
            close_after_reply(sc::format_error("garbage outside a message"),
                              "it sent bytes outside a < > message");
            return;
        case sc::Scan::Kind::TooLong:
            close_after_reply(
                sc::format_error("message too long"),
                fmt::format("it sent a message longer than {} bytes", sc::kMaxMessageLength));
            return;
        }
    }
}

// ---- Commands (socketcand doc/protocol.md) ---------------------------------------------------

void SocketcandSession::handle(const sc::OpenBus& open) {
    if (state_ != State::NoBus) {
        reply_error("a bus is already open");
        return;
    }
    const std::string& served = bus_.config().name;
    if (open.bus != served) {
        // protocol.md: "Otherwise an error is returned and the connection is terminated."
        close_after_reply(sc::format_error(fmt::format("could not open bus {}: this server has {}",
                                                       open.bus, served)),
                          fmt::format("it asked for bus '{}', not '{}'", open.bus, served));
        return;
    }
    open_deadline_.cancel();
    port_ = bus_.connect(name_, config_.limits.tx_queue_capacity);
    last_port_statistics_ = port_->statistics();
    port_->on_receive([this](const Frame& frame) { on_bus_frame(frame); });
    state_ = State::Bcm;
    enqueue(sc::kOk);
    if (on_joined_) {
        on_joined_(*this);
    }
}

void SocketcandSession::handle(const sc::SwitchMode& mode) {
    if (state_ == State::NoBus) {
        reply_error("open a bus first");
        return;
    }
    if (mode.mode != sc::Mode::Raw) {
        reply_error(fmt::format("{} mode is not supported, only raw mode", to_string(mode.mode)));
        return;
    }
    state_ = State::Raw;
    enqueue(sc::kOk);
    settle_ = core::ScopedTimer(bus_.loop(), bus_.loop().after(kRawModeSettle, [this] {
        if (!held_frames_.empty()) {
            enqueue(held_frames_);
            held_frames_.clear();
        }
    }));
}

void SocketcandSession::handle(const sc::Echo&) {
    enqueue(sc::kEcho);
}

void SocketcandSession::handle(const sc::SendFrame& send) {
    if (!port_) {
        reply_error("open a bus first");
        return;
    }
    const SendStatus status = port_->send(sc::frame_for_bus(send.frame));
    if (status == SendStatus::Queued) {
        ++frames_queued_;
        refusing_.reset();
        return;
    }
    // A client that floods a full queue would get as many replies as it sent frames; the
    // port's tx-overflows count each.
    if (refusing_ != status) {
        refusing_ = status;
        reply_error(fmt::format("frame not sent: {}; the following ones are dropped without a "
                                "reply until one is sent",
                                to_string(status)));
    }
}

void SocketcandSession::handle(const sc::NotSupported& command) {
    reply_error(fmt::format("{} is not supported, only raw mode", command.name));
}

void SocketcandSession::handle(const sc::Unknown&) {
    reply_error("unknown command"); // socketcand's own words
}

void SocketcandSession::handle(const sc::Malformed& command) {
    reply_error(command.reason);
}

void SocketcandSession::reply_error(std::string_view reason) {
    enqueue(sc::format_error(reason));
}

// ---- Frames from the bus ----------------------------------------------------------------------

void SocketcandSession::on_bus_frame(const Frame& frame) {
    if (state_ != State::Raw) {
        return; // BCM mode receives nothing without subscriptions, which are not supported
    }
    const core::Duration stamp = bus_.loop().now().time_since_epoch() + config_.epoch_offset;
    std::string message(kFrameSeparator);
    message += sc::format_received(frame, stamp);
    if (settle_.pending()) {
        held_frames_ += message;
        return;
    }
    enqueue(message);
    if (!receive_paused_ && unsent_bytes() > config_.pause_above_bytes) {
        receive_paused_ = true;
        port_->pause_receive(true);
    }
}

void SocketcandSession::close_when_sent() {
    // A script that sends a frame and hangs up at once still has it put on the bus, as
    // socketcand's own write to the kernel would.
    if (frames_waiting() == 0 || port_->error_state() == ErrorState::BusOff) {
        close(std::string(kClientDisconnected));
        return;
    }
    auto& loop = bus_.loop();
    // Checked after the wire event, once the bus has counted the frame as sent.
    drain_observer_ = bus_.add_observer([weak = weak_from_this(), &loop](const WireEvent&) {
        loop.post([weak] {
            if (const auto self = weak.lock(); self && self->frames_waiting() == 0) {
                self->close_soon(std::string(kClientDisconnected));
            }
        });
    });
    drain_deadline_ = core::ScopedTimer(loop, loop.after(kLongestDrain, [this] {
        close_soon(fmt::format("{}; {} frames it sent were still waiting for the bus",
                               kClientDisconnected, frames_waiting()));
    }));
}

std::uint64_t SocketcandSession::frames_waiting() const {
    return port_ ? frames_queued_ - port_->statistics().tx_frames : 0;
}

void SocketcandSession::release_port() {
    if (port_) {
        last_port_statistics_ = port_->statistics();
        port_.reset();
    }
}

void SocketcandSession::resume_if_drained() {
    if (receive_paused_ && port_ && unsent_bytes() <= config_.resume_below_bytes) {
        receive_paused_ = false;
        port_->pause_receive(false); // delivers what waited, which may pause again
    }
}

// ---- Writing ----------------------------------------------------------------------------------

void SocketcandSession::enqueue(std::string_view message) {
    if (state_ == State::Closed) {
        return;
    }
    outgoing_.append(message);
    if (unsent_bytes() > config_.disconnect_above_bytes) {
        close_soon("it does not read what it is sent");
        return;
    }
    flush();
}

void SocketcandSession::flush() {
    if (state_ == State::Closed) {
        return;
    }
    outgoing_.write_next(socket_, [self = shared_from_this()](boost::system::error_code error) {
        self->on_written(error);
    });
}

void SocketcandSession::on_written(boost::system::error_code error) {
    outgoing_.written();
    if (state_ == State::Closed) {
        return;
    }
    if (error) {
        close(fmt::format("write failed: {}", error.message()));
        return;
    }
    flush();
    if (state_ == State::Closing && !outgoing_.writing()) {
        close(close_reason_);
        return;
    }
    resume_if_drained();
}

// ---- Closing ----------------------------------------------------------------------------------

void SocketcandSession::close_after_reply(std::string_view reply, std::string reason) {
    enqueue(reply);
    if (state_ == State::Closed) {
        return;
    }
    state_ = State::Closing;
    close_reason_ = std::move(reason);
    release_port(); // no more bus traffic for a client that is being sent away
    if (!outgoing_.writing()) {
        close(close_reason_);
    }
}

void SocketcandSession::close_soon(std::string reason) {
    if (state_ == State::Closed || state_ == State::Closing) {
        return;
    }
    state_ = State::Closing;
    close_reason_ = std::move(reason);
    boost::asio::post(socket_.get_executor(),
                      [self = shared_from_this()] { self->close(self->close_reason_); });
}

void SocketcandSession::close(const std::string& reason) {
    if (state_ == State::Closed) {
        return;
    }
    state_ = State::Closed;
    open_deadline_.cancel();
    drain_deadline_.cancel();
    if (drain_observer_) {
        bus_.remove_observer(*drain_observer_);
    }
    release_port();
    boost::system::error_code ignored; // the peer may already be gone; nothing to do about it
    socket_.shutdown(boost::asio::ip::tcp::socket::shutdown_both, ignored);
    socket_.close(ignored);
    if (const ClosedHandler handler = std::exchange(on_closed_, nullptr)) {
        handler(*this, reason);
    }
}

} // namespace eposp::can::io
