#include "eposp/service/tcp_server_link.hpp"

#include "byte_stream.hpp"
#include "eposp/core/tcp_address.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <chrono>
#include <fmt/format.h>

namespace eposp::service {

using boost::asio::ip::tcp;
using Socket = ByteStream<tcp::socket>;

namespace {

/// Where a bound acceptor listens; a socket that cannot tell (it can, once bound) reports none.
tcp::endpoint local_endpoint(const tcp::acceptor& acceptor) {
    boost::system::error_code error;
    const tcp::endpoint endpoint = acceptor.local_endpoint(error);
    return error ? tcp::endpoint() : endpoint;
}

} // namespace

/// The listening socket and the host's connection. Shared with the pending accept, so that an
/// accept completing after the link is gone finds it stopped rather than destroyed.
class TcpServerLink::Impl : public std::enable_shared_from_this<Impl> {
public:
    Impl(core::EventLoop& loop, tcp::acceptor acceptor, std::size_t max_unsent_bytes)
        : loop_(loop), acceptor_(std::move(acceptor)), local_(local_endpoint(acceptor_)),
          max_unsent_bytes_(max_unsent_bytes) {}

    void start(TcpServerLink& link) {
        link_ = &link;
        accept();
    }

    void stop() {
        link_ = nullptr;
        retry_timer_.cancel();
        boost::system::error_code ignored; // a listening socket has nothing to report on close
        acceptor_.close(ignored);
        if (host_) {
            host_->close();
            host_.reset();
        }
    }

    void send(std::span<const std::uint8_t> bytes) {
        if (!host_) {
            link_->statistics_.bytes_dropped_no_host += bytes.size();
            return;
        }
        link_->statistics_.bytes_dropped_full += host_->send(bytes);
    }

    void add_bytes_sent(LinkStatistics& statistics) const {
        statistics.bytes_sent = written_by_earlier_hosts_ + (host_ ? host_->bytes_written() : 0);
    }

    const tcp::endpoint& local() const { return local_; }
    bool host_connected() const { return host_ != nullptr; }

private:
    void accept() {
        acceptor_.async_accept(
            [self = shared_from_this()](boost::system::error_code error, tcp::socket socket) {
                self->on_accepted(error, std::move(socket));
            });
    }

    void on_accepted(boost::system::error_code error, tcp::socket socket) {
        if (link_ == nullptr) {
            return;
        }
        if (error) {
            // Out of file descriptors, a connection reset before it was accepted, ...: try
            // again a little later instead of spinning on an error that persists.
            constexpr auto kRetryDelay = std::chrono::milliseconds(100);
            retry_timer_ = core::ScopedTimer(loop_, loop_.after(kRetryDelay, [this] { accept(); }));
            return;
        }
        if (host_) {
            boost::system::error_code ignored; // it is turned away whatever it says
            socket.close(ignored);
            ++link_->statistics_.hosts_turned_away;
        } else {
            serve(std::move(socket));
        }
        accept();
    }

    void serve(tcp::socket socket) {
        boost::system::error_code error;
        const auto remote = socket.remote_endpoint(error);
        remote_ = error ? std::string("an unknown address") : core::format_endpoint(remote);
        // Each answer goes out as soon as it is sent, as on a serial line; a socket that refuses
        // the option only adds latency.
        socket.set_option(tcp::no_delay(true), error);
        host_ = std::make_shared<Socket>(std::move(socket), max_unsent_bytes_);
        host_->start([this](std::span<const std::uint8_t> bytes) { link_->deliver(bytes); },
                     [this](boost::system::error_code) { hang_up(); });
    }

    void hang_up() {
        written_by_earlier_hosts_ += host_->bytes_written();
        link_->statistics_.bytes_dropped_no_host += host_->stop();
        host_->close();
        host_.reset();
        link_->report({LinkEvent::Kind::HungUp, fmt::format("host {} disconnected", remote_)});
    }

    core::EventLoop& loop_;
    tcp::acceptor acceptor_;
    tcp::endpoint local_;
    std::size_t max_unsent_bytes_;
    TcpServerLink* link_ = nullptr;
    std::shared_ptr<Socket> host_;
    std::string remote_;
    core::ScopedTimer retry_timer_;
    std::uint64_t written_by_earlier_hosts_ = 0;
};

core::Result<std::unique_ptr<TcpServerLink>> TcpServerLink::open(core::EventLoop& loop,
                                                                 const std::string& address,
                                                                 TcpServerLinkOptions options) {
    const auto parsed = core::parse_tcp_address(address);
    if (!parsed) {
        return core::Error{parsed.error()};
    }
    boost::system::error_code error;
    const auto resolved = tcp::resolver(loop.io()).resolve(
        parsed->host, std::to_string(parsed->port),
        tcp::resolver::passive | tcp::resolver::numeric_service, error);
    if (error || resolved.empty()) {
        return core::Error{fmt::format("cannot listen on {}: {}", address, error.message())};
    }
    const tcp::endpoint endpoint = resolved.begin()->endpoint();
    tcp::acceptor acceptor(loop.io());
    const auto failed = [&](std::string_view step) {
        return core::Error{
            fmt::format("cannot listen on {}: {} failed: {}", address, step, error.message())};
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
    auto impl = std::make_shared<Impl>(loop, std::move(acceptor), options.max_unsent_bytes);
    std::unique_ptr<TcpServerLink> link(new TcpServerLink(impl));
    impl->start(*link);
    return link;
}

TcpServerLink::TcpServerLink(std::shared_ptr<Impl> impl)
    : impl_(std::move(impl)), name_(fmt::format("tcp {}", core::format_endpoint(impl_->local()))) {}

TcpServerLink::~TcpServerLink() {
    impl_->stop();
}

void TcpServerLink::send(std::span<const std::uint8_t> bytes) {
    impl_->send(bytes);
}

LinkStatistics TcpServerLink::statistics() const {
    LinkStatistics statistics = statistics_;
    impl_->add_bytes_sent(statistics);
    return statistics;
}

std::uint16_t TcpServerLink::port() const {
    return impl_->local().port();
}

std::string TcpServerLink::address() const {
    return core::format_endpoint(impl_->local());
}

bool TcpServerLink::host_connected() const {
    return impl_->host_connected();
}

} // namespace eposp::service
