#include "eposp/core/tcp_address.hpp"

#include <gtest/gtest.h>

namespace eposp::core {
namespace {

TEST(TcpAddress, ReadsHostAndPortBracketedIpv6AndAPortAlone) {
    const auto named = parse_tcp_address("localhost:29536");
    ASSERT_TRUE(named) << named.error();
    EXPECT_EQ(named->host, "localhost");
    EXPECT_EQ(named->port, 29536);

    const auto ipv6 = parse_tcp_address("[::1]:4001");
    ASSERT_TRUE(ipv6) << ipv6.error();
    EXPECT_EQ(ipv6->host, "::1");
    EXPECT_EQ(ipv6->port, 4001);

    const auto port_alone = parse_tcp_address("0");
    ASSERT_TRUE(port_alone) << port_alone.error();
    EXPECT_EQ(port_alone->host, "127.0.0.1");
    EXPECT_EQ(port_alone->port, 0);
}

TEST(TcpAddress, RefusesWhatIsNotAnAddressAndSaysWhatOneLooksLike) {
    for (const char* text : {"", ":", "host:", ":4001", "::1:4001", "[]:4001", "host:65536",
                             "host:-1", "host:40x1", "host:port"}) {
        const auto parsed = parse_tcp_address(text);
        ASSERT_FALSE(parsed) << text;
        EXPECT_NE(parsed.error().find("HOST:PORT"), std::string::npos) << parsed.error();
    }
}

TEST(TcpAddress, ShowsIpv6EndpointsInBrackets) {
    using boost::asio::ip::make_address;
    using boost::asio::ip::tcp;
    EXPECT_EQ(format_endpoint(tcp::endpoint(make_address("127.0.0.1"), 29536)), "127.0.0.1:29536");
    EXPECT_EQ(format_endpoint(tcp::endpoint(make_address("::1"), 4001)), "[::1]:4001");
}

} // namespace
} // namespace eposp::core
