// The TCP server and client links over loopback, both on one real-time loop; every wait ends
// as soon as what it waits for has happened.
#include "eposp/service/tcp_client_link.hpp"
#include "eposp/service/tcp_server_link.hpp"
#include "link_test_support.hpp"

#include <gtest/gtest.h>

namespace eposp::service {
namespace {

using namespace test;

class TcpLinkTest : public testing::Test {
protected:
    void SetUp() override {
        auto opened = TcpServerLink::open(loop, "127.0.0.1:0");
        ASSERT_TRUE(opened) << opened.error();
        server = std::move(*opened);
        server_recorder = std::make_unique<LinkRecorder>(*server);
    }

    std::unique_ptr<TcpClientLink> connect() {
        auto client = TcpClientLink::open(loop, server->address());
        EXPECT_TRUE(client) << client.error();
        return std::move(*client);
    }

    core::EventLoop loop{core::Pace::RealTime};
    std::unique_ptr<TcpServerLink> server;
    std::unique_ptr<LinkRecorder> server_recorder;
};

TEST_F(TcpLinkTest, PortZeroPicksAFreePortOnLoopback) {
    EXPECT_NE(server->port(), 0);
    EXPECT_EQ(server->address(), "127.0.0.1:" + std::to_string(server->port()));
    EXPECT_EQ(server->name(), "tcp " + server->address());
}

TEST_F(TcpLinkTest, BytesTravelBothWaysBetweenClientAndServer) {
    auto client = connect();
    LinkRecorder client_recorder(*client);
    client->send(bytes_of(std::string("\x90\x02\x10\x02\x41\x60\x00\x01\x64\xCF", 10))); // queued
    ASSERT_TRUE(run_until(loop, [&] { return server_recorder->received.size() == 10; }));
    EXPECT_EQ(server_recorder->received,
              std::string("\x90\x02\x10\x02\x41\x60\x00\x01\x64\xCF", 10));
    EXPECT_TRUE(client->connected());
    EXPECT_TRUE(server->host_connected());

    server->send(bytes_of("answer"));
    ASSERT_TRUE(run_until(loop, [&] { return client_recorder.received == "answer"; }));
    EXPECT_TRUE(server_recorder->events.empty());
    EXPECT_TRUE(client_recorder.events.empty());
}

TEST_F(TcpLinkTest, ASecondHostIsClosedAtOnceWithNothingSentAndTheFirstStaysServed) {
    auto first = connect();
    LinkRecorder first_recorder(*first);
    first->send(bytes_of("1"));
    ASSERT_TRUE(run_until(loop, [&] { return server_recorder->received == "1"; }));

    auto second = connect();
    LinkRecorder second_recorder(*second);
    second->send(bytes_of("2"));
    ASSERT_TRUE(run_until(loop, [&] { return second->closed(); }));
    EXPECT_TRUE(second_recorder.received.empty());
    EXPECT_EQ(server->statistics().hosts_turned_away, 1u);

    server->send(bytes_of("to the first"));
    ASSERT_TRUE(run_until(loop, [&] { return first_recorder.received == "to the first"; }));
    EXPECT_EQ(server_recorder->received, "1") << "nothing of the second host's";
    EXPECT_TRUE(server_recorder->events.empty());
}

TEST_F(TcpLinkTest, AHostLeavingIsAHangUpAndTheNextIsServed) {
    {
        auto first = connect();
        first->send(bytes_of("first"));
        ASSERT_TRUE(run_until(loop, [&] { return server_recorder->received == "first"; }));
    }
    ASSERT_TRUE(run_until(loop, [&] { return !server_recorder->events.empty(); }));
    EXPECT_EQ(server_recorder->events[0].kind, LinkEvent::Kind::HungUp);
    EXPECT_FALSE(server->host_connected());
    server->send(bytes_of("lost"));
    EXPECT_EQ(server->statistics().bytes_dropped_no_host, 4u);

    auto next = connect();
    LinkRecorder next_recorder(*next);
    next->send(bytes_of("next"));
    ASSERT_TRUE(run_until(loop, [&] { return server_recorder->received == "firstnext"; }));
    server->send(bytes_of("welcome"));
    ASSERT_TRUE(run_until(loop, [&] { return next_recorder.received == "welcome"; }));
    EXPECT_FALSE(server->closed());
}

TEST_F(TcpLinkTest, TheServerClosingClosesTheClient) {
    auto client = connect();
    LinkRecorder recorder(*client);
    ASSERT_TRUE(run_until(loop, [&] { return server->host_connected(); }));
    server.reset();
    ASSERT_TRUE(run_until(loop, [&] { return client->closed(); }));
    ASSERT_EQ(recorder.events.size(), 1u);
    EXPECT_EQ(recorder.events[0].kind, LinkEvent::Kind::Closed);
    EXPECT_NE(recorder.events[0].text.find("closed the connection"), std::string::npos)
        << recorder.events[0].text;
}

TEST_F(TcpLinkTest, AClientThatCannotConnectIsClosedWithTheReason) {
    const std::string address = server->address();
    server.reset(); // nobody listens there now
    auto client = TcpClientLink::open(loop, address);
    ASSERT_TRUE(client) << client.error();
    LinkRecorder recorder(**client);
    ASSERT_TRUE(run_until(loop, [&] { return (*client)->closed(); }));
    EXPECT_NE(recorder.events.at(0).text.find("cannot connect to " + address), std::string::npos)
        << recorder.events.at(0).text;
}

TEST_F(TcpLinkTest, MalformedOrTakenAddressesAreRefused) {
    for (const char* bad : {"", "localhost:", ":80", "1:2:3", "127.0.0.1:65536", "port"}) {
        auto refused = TcpServerLink::open(loop, bad);
        ASSERT_FALSE(refused) << bad;
        EXPECT_NE(refused.error().find("is not a TCP address"), std::string::npos)
            << refused.error();
    }
    auto taken = TcpServerLink::open(loop, server->address());
    ASSERT_FALSE(taken);
    EXPECT_NE(taken.error().find("bind failed"), std::string::npos) << taken.error();
}

} // namespace
} // namespace eposp::service
