#include "eposp/core/tcp_address.hpp"

#include <charconv>
#include <fmt/format.h>
#include <optional>

namespace eposp::core {
namespace {

std::optional<std::uint16_t> parse_port(std::string_view text) {
    std::uint16_t port = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), port);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return port;
}

Error malformed(std::string_view text) {
    return Error{fmt::format(
        "'{}' is not a TCP address (HOST:PORT, [IPV6]:PORT or PORT, port 0 to 65535)", text)};
}

} // namespace

Result<TcpAddress> parse_tcp_address(std::string_view text) {
    const std::size_t colon = text.rfind(':');
    if (colon == std::string_view::npos) {
        const auto port = parse_port(text);
        return port ? Result<TcpAddress>(TcpAddress{"127.0.0.1", *port}) : malformed(text);
    }
    std::string_view host = text.substr(0, colon);
    if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
        host = host.substr(1, host.size() - 2);
    } else if (host.find(':') != std::string_view::npos) {
        return malformed(text); // an IPv6 address needs brackets to tell it from the port
    }
    const auto port = parse_port(text.substr(colon + 1));
    if (host.empty() || !port) {
        return malformed(text);
    }
    return TcpAddress{std::string(host), *port};
}

std::string format_endpoint(const boost::asio::ip::tcp::endpoint& endpoint) {
    const auto address = endpoint.address();
    return address.is_v6() ? fmt::format("[{}]:{}", address.to_string(), endpoint.port())
                           : fmt::format("{}:{}", address.to_string(), endpoint.port());
}

} // namespace eposp::core
