#pragma once

// TCP addresses as users write them on the command line and as messages show them.

#include "eposp/core/result.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <cstdint>
#include <string>
#include <string_view>

namespace eposp::core {

struct TcpAddress {
    std::string host;
    std::uint16_t port = 0;
};

/// "HOST:PORT", "[IPV6]:PORT", or "PORT" alone for 127.0.0.1.
Result<TcpAddress> parse_tcp_address(std::string_view text);

/// "127.0.0.1:4001", "[::1]:4001".
std::string format_endpoint(const boost::asio::ip::tcp::endpoint& endpoint);

} // namespace eposp::core
