#include "eposp/can/io/socketcand_server.hpp"

#include "eposp/can/io/socketcand_protocol.hpp"
#include "eposp/core/tcp_address.hpp"
#include "socketcand_session.hpp"

#include <algorithm>
#include <boost/asio/ip/tcp.hpp>
#include <chrono>
#include <fmt/format.h>
#include <vector>

namespace eposp::can::io {

using boost::asio::ip::tcp;

/// The listening socket and the sessions. Shared with the pending accept, so that an accept
/// completing after the server is gone finds it stopped rather than destroyed.
class SocketcandServer::Impl : public std::enable_shared_from_this<Impl> {
public:
    Impl(VirtualBus& bus, SocketcandServerConfig config, tcp::acceptor acceptor)
        : bus_(bus), config_(std::move(config)), acceptor_(std::move(acceptor)),
          local_(acceptor_.local_endpoint()) {}

    void accept();
    void stop();

    const tcp::endpoint& local() const { return local_; }
    std::size_t client_count() const { return sessions_.size(); }
    std::vector<SocketcandClientInfo> clients() const;
    const SocketcandServerStatistics& statistics() const { return statistics_; }
    void on_client_event(EventHandler handler) { event_handler_ = std::move(handler); }

private:
    void on_accepted(boost::system::error_code error, tcp::socket socket);
    void turn_away(tcp::socket socket);
    void on_session_joined(const SocketcandSession& session);
    void on_session_closed(SocketcandSession& session, const std::string& reason);
    void report(SocketcandClientEvent event);

    VirtualBus& bus_;
    SocketcandServerConfig config_;
    tcp::acceptor acceptor_;
    tcp::endpoint local_;
    std::vector<std::shared_ptr<SocketcandSession>> sessions_;
    std::uint64_t clients_accepted_ = 0;
    SocketcandServerStatistics statistics_;
    EventHandler event_handler_;
    core::ScopedTimer retry_timer_;
    bool stopped_ = false;
};

void SocketcandServer::Impl::accept() {
    acceptor_.async_accept(
        [self = shared_from_this()](boost::system::error_code error, tcp::socket socket) {
            self->on_accepted(error, std::move(socket));
        });
}

void SocketcandServer::Impl::on_accepted(boost::system::error_code error, tcp::socket socket) {
    if (stopped_) {
        return;
    }
    if (error) {
        // Out of file descriptors, a connection reset before it was accepted, ...: try again a
        // little later instead of spinning on an error that persists.
        constexpr auto kRetryDelay = std::chrono::milliseconds(100);
        retry_timer_ =
            core::ScopedTimer(bus_.loop(), bus_.loop().after(kRetryDelay, [this] { accept(); }));
        return;
    }
    if (sessions_.size() >= config_.limits.max_clients) {
        turn_away(std::move(socket));
        accept();
        return;
    }
    auto session = std::make_shared<SocketcandSession>(
        std::move(socket), fmt::format("socketcand-{}", ++clients_accepted_), bus_, config_,
        [this](const SocketcandSession& joined) { on_session_joined(joined); },
        [this](SocketcandSession& closed, const std::string& reason) {
            on_session_closed(closed, reason);
        });
    sessions_.push_back(session);
    session->start();
    accept();
}

void SocketcandServer::Impl::turn_away(tcp::socket socket) {
    boost::system::error_code error;
    const auto endpoint = socket.remote_endpoint(error);
    const std::string remote =
        error ? std::string("unknown address") : core::format_endpoint(endpoint);
    // The reply fits an empty send buffer; a non-blocking write never holds up the loop.
    socket.non_blocking(true, error);
    const std::string reply = socketcand::format_error("too many clients");
    socket.write_some(boost::asio::buffer(reply), error);
    socket.close(error);
    ++statistics_.dropped;
    ++statistics_.turned_away;
    report({SocketcandClientEvent::Kind::Dropped,
            {},
            remote,
            fmt::format("{} clients are connected already", config_.limits.max_clients)});
}

void SocketcandServer::Impl::on_session_joined(const SocketcandSession& session) {
    ++statistics_.joined;
    report({SocketcandClientEvent::Kind::Joined, session.name(), session.remote(), {}});
}

void SocketcandServer::Impl::on_session_closed(SocketcandSession& session,
                                               const std::string& reason) {
    const auto it =
        std::ranges::find_if(sessions_, [&](const auto& s) { return s.get() == &session; });
    if (it == sessions_.end()) {
        return;
    }
    const std::shared_ptr<SocketcandSession> keep = *it; // the report still reads it
    sessions_.erase(it);
    if (!session.joined()) {
        ++statistics_.dropped;
        report({SocketcandClientEvent::Kind::Dropped, {}, session.remote(), reason});
        return;
    }
    const PortStatistics port = *session.info().port;
    ++statistics_.left;
    statistics_.left_tx_frames += port.tx_frames;
    statistics_.left_rx_frames += port.rx_frames;
    statistics_.left_tx_overflows += port.tx_overflows;
    statistics_.left_rx_overflows += port.rx_overflows;
    report({SocketcandClientEvent::Kind::Left, session.name(), session.remote(), reason});
}

void SocketcandServer::Impl::report(SocketcandClientEvent event) {
    if (event_handler_) {
        event_handler_(event);
    }
}

std::vector<SocketcandClientInfo> SocketcandServer::Impl::clients() const {
    std::vector<SocketcandClientInfo> infos;
    for (const auto& session : sessions_) {
        infos.push_back(session->info());
    }
    return infos;
}

void SocketcandServer::Impl::stop() {
    stopped_ = true;
    retry_timer_.cancel();
    boost::system::error_code ignored; // a listening socket has nothing to report on close
    acceptor_.close(ignored);
    for (const auto& session : std::exchange(sessions_, {})) {
        session->abort();
    }
}

core::Result<std::unique_ptr<SocketcandServer>>
SocketcandServer::open(VirtualBus& bus, SocketcandServerConfig config) {
    const SocketcandLimits& limits = config.limits;
    if (limits.tx_queue_capacity == 0 || limits.max_clients == 0 ||
        limits.open_timeout <= core::Duration::zero()) {
        return core::Error{"a socketcand server needs a transmit queue, room for a client and "
                           "time for it to open the bus"};
    }
    const auto address = core::parse_tcp_address(config.listen);
    if (!address) {
        return core::Error{
            fmt::format("'{}' is not an address to listen on (HOST:PORT)", config.listen)};
    }
    auto& io = bus.loop().io();
    boost::system::error_code error;
    const auto resolved =
        tcp::resolver(io).resolve(address->host, std::to_string(address->port),
                                  tcp::resolver::passive | tcp::resolver::numeric_service, error);
    if (error || resolved.empty()) {
        return core::Error{fmt::format("cannot listen on {}: {}", config.listen, error.message())};
    }
    const tcp::endpoint endpoint = resolved.begin()->endpoint();
    tcp::acceptor acceptor(io);
    const auto failed = [&](std::string_view step) {
        return core::Error{fmt::format("cannot listen on {}: {} failed: {}", config.listen, step,
                                       error.message())};
    };
    if (acceptor.open(endpoint.protocol(), error)) {
        return failed("socket");
    }
    // Lets a restarted server take its port back while old connections linger in TIME_WAIT.
    if (acceptor.set_option(tcp::acceptor::reuse_address(true), error)) {
        return failed("setsockopt");
    }
    if (acceptor.bind(endpoint, error)) {
        return failed("bind");
    }
    if (acceptor.listen(tcp::socket::max_listen_connections, error)) {
        return failed("listen");
    }
    auto impl = std::make_shared<Impl>(bus, std::move(config), std::move(acceptor));
    impl->accept();
    return std::unique_ptr<SocketcandServer>(new SocketcandServer(impl));
}

SocketcandServer::SocketcandServer(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}

SocketcandServer::~SocketcandServer() {
    impl_->stop();
}

std::uint16_t SocketcandServer::port() const {
    return impl_->local().port();
}

std::string SocketcandServer::address() const {
    return core::format_endpoint(impl_->local());
}

std::size_t SocketcandServer::client_count() const {
    return impl_->client_count();
}

std::vector<SocketcandClientInfo> SocketcandServer::clients() const {
    return impl_->clients();
}

SocketcandServerStatistics SocketcandServer::statistics() const {
    return impl_->statistics();
}

void SocketcandServer::on_client_event(EventHandler handler) {
    impl_->on_client_event(std::move(handler));
}

} // namespace eposp::can::io
