#pragma once

// Internal: TCP addresses as users write them and as messages show them.

#include <boost/asio/ip/tcp.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::can::io {

struct ListenAddress {
    std::string host;
    std::uint16_t port = 0;
};

/// "HOST:PORT", "[IPV6]:PORT", or "PORT" alone for 127.0.0.1. Nothing when malformed.
std::optional<ListenAddress> parse_listen_address(std::string_view text);

/// "127.0.0.1:29536", "[::1]:29536".
std::string format_endpoint(const boost::asio::ip::tcp::endpoint& endpoint);

} // namespace eposp::can::io
