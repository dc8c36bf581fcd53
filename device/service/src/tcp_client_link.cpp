#include "eposp/service/tcp_client_link.hpp"

#include "byte_stream.hpp"
#include "eposp/core/tcp_address.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/error.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <fmt/format.h>

namespace eposp::service {

using boost::asio::ip::tcp;
using Socket = ByteStream<tcp::socket>;

/// Shared with the pending connect, so that a connect completing after the link is gone finds
/// it detached rather than destroyed.
class TcpClientLink::Impl : public std::enable_shared_from_this<Impl> {
public:
    Impl(core::EventLoop& loop, std::string address, std::size_t max_unsent_bytes)
        : stream_(std::make_shared<Socket>(tcp::socket(loop.io()), max_unsent_bytes)),
          address_(std::move(address)) {}

    void start(TcpClientLink& link, const tcp::resolver::results_type& endpoints) {
        link_ = &link;
        boost::asio::async_connect(
            stream_->stream(), endpoints,
            [self = shared_from_this()](boost::system::error_code error, const tcp::endpoint&) {
                self->on_connected(error);
            });
    }

    void detach() {
        link_ = nullptr;
        stream_->close();
    }

    void send(std::span<const std::uint8_t> bytes) {
        if (link_->closed()) {
            link_->statistics_.bytes_dropped_no_host += bytes.size();
            return;
        }
        link_->statistics_.bytes_dropped_full += stream_->send(bytes);
    }

    void add_bytes_sent(LinkStatistics& statistics) const {
        statistics.bytes_sent = stream_->bytes_written();
    }

    bool connected() const { return connected_; }

private:
    void on_connected(boost::system::error_code error) {
        if (link_ == nullptr) {
            return;
        }
        if (error) {
            end(fmt::format("cannot connect to {}: {}", address_, error.message()));
            return;
        }
        connected_ = true;
        boost::system::error_code ignored; // without it answers only come later
        stream_->stream().set_option(tcp::no_delay(true), ignored);
        stream_->start(
            [this](std::span<const std::uint8_t> bytes) { link_->deliver(bytes); },
            [this](boost::system::error_code ended) {
                end(ended == boost::asio::error::eof
                        ? fmt::format("{} closed the connection", address_)
                        : fmt::format("reading from {} failed: {}", address_, ended.message()));
            });
    }

    void end(std::string reason) {
        connected_ = false;
        link_->statistics_.bytes_dropped_no_host += stream_->stop();
        link_->report({LinkEvent::Kind::Closed, std::move(reason)});
    }

    std::shared_ptr<Socket> stream_;
    std::string address_;
    TcpClientLink* link_ = nullptr;
    bool connected_ = false;
};

core::Result<std::unique_ptr<TcpClientLink>> TcpClientLink::open(core::EventLoop& loop,
                                                                 const std::string& address,
                                                                 std::size_t max_unsent_bytes) {
    const auto parsed = core::parse_tcp_address(address);
    if (!parsed) {
        return core::Error{parsed.error()};
    }
    boost::system::error_code error;
    const auto endpoints = tcp::resolver(loop.io()).resolve(
        parsed->host, std::to_string(parsed->port), tcp::resolver::numeric_service, error);
    if (error || endpoints.empty()) {
        return core::Error{fmt::format("cannot resolve {}: {}", parsed->host, error.message())};
    }
    auto impl = std::make_shared<Impl>(loop, address, max_unsent_bytes);
    std::unique_ptr<TcpClientLink> link(new TcpClientLink(fmt::format("tcp {}", address), impl));
    impl->start(*link, endpoints);
    return link;
}

TcpClientLink::TcpClientLink(std::string name, std::shared_ptr<Impl> impl)
    : name_(std::move(name)), impl_(std::move(impl)) {}

TcpClientLink::~TcpClientLink() {
    impl_->detach();
}

void TcpClientLink::send(std::span<const std::uint8_t> bytes) {
    impl_->send(bytes);
}

LinkStatistics TcpClientLink::statistics() const {
    LinkStatistics statistics = statistics_;
    impl_->add_bytes_sent(statistics);
    return statistics;
}

bool TcpClientLink::connected() const {
    return impl_->connected();
}

} // namespace eposp::service
