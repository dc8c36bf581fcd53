// The socketcand server over real loopback TCP: the loop runs in real time with the test's
// clients on the same io_context, each wait is bounded by a deadline and ends as soon as what
// it waits for has happened.
#include "eposp/can/io/socketcand_protocol.hpp"
#include "eposp/can/io/socketcand_server.hpp"
#include "eposp/canopen/node.hpp"

#include <algorithm>
#include <array>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <cctype>
#include <deque>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <iterator>
#include <optional>

namespace eposp::can::io {
namespace {

using namespace std::chrono_literals;
using boost::asio::ip::tcp;

constexpr core::Duration kEpoch = 1'700'000'000s;
constexpr core::Duration kDeadline = 5s;

struct ReceivedFrame {
    Frame frame;
    std::string stamp;
};

bool all_hex(std::string_view text) {
    return std::ranges::all_of(text, [](char c) { return std::isxdigit(c) && !std::islower(c); });
}

/// `< frame ID SEC.USEC DATA >` exactly as socketcand writes it: ID with 3 or 8 upper-case hex
/// digits, SEC.USEC with 6 decimals, DATA as upper-case hex without spaces, single spaces
/// between the fields.
std::optional<ReceivedFrame> parse_frame_message(std::string_view message) {
    constexpr std::string_view kStart = "< frame ";
    constexpr std::string_view kEnd = " >";
    if (!message.starts_with(kStart) || !message.ends_with(kEnd)) {
        return std::nullopt;
    }
    const std::string_view fields =
        message.substr(kStart.size(), message.size() - kStart.size() - kEnd.size());
    const std::size_t first = fields.find(' ');
    const std::size_t second = fields.find(' ', first + 1);
    if (first == std::string_view::npos || second == std::string_view::npos) {
        return std::nullopt;
    }
    const std::string_view id = fields.substr(0, first);
    const std::string_view stamp = fields.substr(first + 1, second - first - 1);
    const std::string_view data = fields.substr(second + 1);
    const std::size_t dot = stamp.find('.');
    if ((id.size() != 3 && id.size() != 8) || !all_hex(id) || !all_hex(data) ||
        data.size() % 2 != 0 || data.size() > 2 * kMaxDataLength || dot == std::string_view::npos ||
        stamp.size() - dot - 1 != 6) {
        return std::nullopt;
    }
    std::vector<std::uint8_t> bytes;
    for (std::size_t i = 0; i < data.size(); i += 2) {
        bytes.push_back(
            static_cast<std::uint8_t>(std::stoul(std::string(data.substr(i, 2)), nullptr, 16)));
    }
    const auto value = static_cast<std::uint32_t>(std::stoul(std::string(id), nullptr, 16));
    return ReceivedFrame{Frame::data_frame(value, bytes, id.size() == 8), std::string(stamp)};
}

/// A socketcand client on the loop's io_context: writes what it is given in order and collects
/// every `< ... >` message the server sends.
class TestClient {
public:
    TestClient(core::EventLoop& loop, std::uint16_t port, std::function<void()> on_progress,
               std::optional<int> receive_buffer = std::nullopt)
        : socket_(loop.io()), on_progress_(std::move(on_progress)) {
        socket_.open(tcp::v4());
        if (receive_buffer) {
            socket_.set_option(tcp::socket::receive_buffer_size(*receive_buffer));
        }
        socket_.async_connect({boost::asio::ip::make_address_v4("127.0.0.1"), port},
                              [this](boost::system::error_code error) {
                                  if (error) {
                                      closed_ = true;
                                      on_progress_();
                                      return;
                                  }
                                  connected_ = true;
                                  if (!outbox_.empty()) {
                                      write_next();
                                  }
                                  read();
                              });
    }

    void send(std::string_view text) {
        outbox_.emplace_back(text);
        if (connected_ && outbox_.size() == 1) {
            write_next();
        }
    }
    /// Stops reading after the read in progress, so that the server's output piles up.
    void stop_reading() { reading_ = false; }
    void start_reading() {
        reading_ = true;
        if (!read_pending_) {
            read();
        }
    }
    void disconnect() { socket_.close(); }

    const std::vector<std::string>& messages() const { return messages_; }
    /// Each read as it came from the socket.
    const std::vector<std::string>& reads() const { return reads_; }
    bool closed() const { return closed_; }
    /// The frames received, in order.
    std::vector<Frame> frames() const {
        std::vector<Frame> frames;
        for (const std::string& message : messages_) {
            if (const auto received = parse_frame_message(message)) {
                frames.push_back(received->frame);
            }
        }
        return frames;
    }

private:
    void write_next() {
        boost::asio::async_write(socket_, boost::asio::buffer(outbox_.front()),
                                 [this](boost::system::error_code error, std::size_t) {
                                     if (error) {
                                         return; // the read side reports the closed connection
                                     }
                                     outbox_.pop_front();
                                     if (!outbox_.empty()) {
                                         write_next();
                                     }
                                 });
    }

    void read() {
        read_pending_ = true;
        socket_.async_read_some(boost::asio::buffer(buffer_),
                                [this](boost::system::error_code error, std::size_t size) {
                                    read_pending_ = false;
                                    if (error) {
                                        closed_ = true;
                                        on_progress_();
                                        return;
                                    }
                                    input_.append(buffer_.data(), size);
                                    reads_.emplace_back(buffer_.data(), size);
                                    for (std::size_t end = input_.find('>');
                                         end != std::string::npos; end = input_.find('>')) {
                                        const std::size_t start = std::min(input_.find('<'), end);
                                        messages_.push_back(input_.substr(start, end + 1 - start));
                                        input_.erase(0, end + 1);
                                    }
                                    on_progress_();
                                    if (reading_) {
                                        read();
                                    }
                                });
    }

    tcp::socket socket_;
    std::function<void()> on_progress_;
    std::deque<std::string> outbox_;
    std::array<char, 4096> buffer_{};
    std::string input_;
    std::vector<std::string> messages_;
    std::vector<std::string> reads_;
    bool connected_ = false;
    bool reading_ = true;
    bool read_pending_ = false;
    bool closed_ = false;
};

class SocketcandServerTest : public testing::Test {
protected:
    void SetUp() override {
        start_server({});
        node->on_receive([this](const Frame& frame) {
            node_received.push_back(frame);
            progress();
        });
    }

    void start_server(SocketcandServerConfig config) {
        server.reset();
        config.listen = "127.0.0.1:0";
        config.epoch_offset = kEpoch;
        auto opened = SocketcandServer::open(bus, std::move(config));
        ASSERT_TRUE(opened) << opened.error();
        server = std::move(*opened);
        server->on_client_event([this](const SocketcandClientEvent& event) {
            events.push_back(event);
            progress();
        });
    }

    /// Runs the loop until `done()` holds, for kDeadline at most; whether it holds.
    bool run_until(std::function<bool()> done) {
        if (done()) {
            return true;
        }
        waiting_for_ = std::move(done);
        loop.run_for(kDeadline);
        const bool held = waiting_for_();
        waiting_for_ = nullptr;
        return held;
    }

    void progress() {
        if (waiting_for_ && waiting_for_()) {
            loop.stop();
        }
    }

    std::unique_ptr<TestClient> connect(std::optional<int> receive_buffer = std::nullopt) {
        return std::make_unique<TestClient>(
            loop, server->port(), [this] { progress(); }, receive_buffer);
    }

    /// Connects and goes through the handshake python-can does.
    std::unique_ptr<TestClient> join(std::optional<int> receive_buffer = std::nullopt) {
        auto client = connect(receive_buffer);
        const auto received = [&](std::size_t n) {
            return run_until([&] { return client->messages().size() >= n; });
        };
        EXPECT_TRUE(received(1));
        client->send("< open can0 >");
        EXPECT_TRUE(received(2));
        client->send("< rawmode >");
        EXPECT_TRUE(received(3));
        EXPECT_EQ(client->messages(), (std::vector<std::string>{"< hi >", "< ok >", "< ok >"}));
        return client;
    }

    /// Whether a client left, or a connection was dropped, for `reason`.
    bool ended(SocketcandClientEvent::Kind kind, std::string_view reason) const {
        return std::ranges::any_of(events, [&](const SocketcandClientEvent& event) {
            return event.kind == kind && event.reason == reason;
        });
    }
    bool left(std::string_view reason) const {
        return ended(SocketcandClientEvent::Kind::Left, reason);
    }
    bool dropped(std::string_view reason) const {
        return ended(SocketcandClientEvent::Kind::Dropped, reason);
    }

    core::EventLoop loop{core::Pace::RealTime};
    VirtualBus bus{loop, BusConfig{.name = "can0"}};
    std::unique_ptr<VirtualPort> node = bus.connect("node");
    std::vector<Frame> node_received;
    std::unique_ptr<SocketcandServer> server;
    std::vector<SocketcandClientEvent> events;

private:
    std::function<bool()> waiting_for_;
};

TEST_F(SocketcandServerTest, ListensOnAnEphemeralLoopbackPort) {
    EXPECT_NE(server->port(), 0);
    EXPECT_EQ(server->address(), "127.0.0.1:" + std::to_string(server->port()));
}

TEST_F(SocketcandServerTest, RefusesAddressesItCannotListenOn) {
    for (const char* address : {"nonsense", "127.0.0.1:", "127.0.0.1:99999", "::1:80", ""}) {
        const auto opened = SocketcandServer::open(bus, {.listen = address});
        ASSERT_FALSE(opened) << address;
        EXPECT_NE(opened.error().find("not an address"), std::string::npos) << opened.error();
    }
    const auto taken = SocketcandServer::open(bus, {.listen = server->address()});
    ASSERT_FALSE(taken);
    EXPECT_NE(taken.error().find("cannot listen on " + server->address()), std::string::npos)
        << taken.error();
}

TEST_F(SocketcandServerTest, FullSessionCarriesFramesBothWays) {
    auto client = join();
    EXPECT_EQ(server->client_count(), 1U);
    ASSERT_EQ(events.size(), 1U);
    EXPECT_EQ(events[0].kind, SocketcandClientEvent::Kind::Joined);
    EXPECT_EQ(events[0].client, "socketcand-1");

    ASSERT_EQ(node->send(Frame::data_frame(0x181, {0x01, 0x02})), SendStatus::Queued);
    ASSERT_TRUE(run_until([&] { return client->messages().size() == 4; }));
    const auto received = parse_frame_message(client->messages()[3]);
    ASSERT_TRUE(received) << client->messages()[3];
    EXPECT_EQ(received->frame, Frame::data_frame(0x181, {0x01, 0x02}));
    const auto seconds = std::stoll(received->stamp);
    EXPECT_GE(seconds, kEpoch.count() / 1'000'000'000); // loop time plus the epoch offset
    EXPECT_LT(seconds, kEpoch.count() / 1'000'000'000 + 60);

    client->send("< send 123 2 AA BB >");
    ASSERT_TRUE(run_until([&] { return node_received.size() == 1; }));
    EXPECT_EQ(node_received[0], Frame::data_frame(0x123, {0xAA, 0xBB}));
}

// A client sends faster than the bus carries (one TCP write of many frames): the session's port
// buffers them as a gateway does, and every one reaches the bus, in order.
TEST_F(SocketcandServerTest, ABurstOfFramesInOneWriteReachesTheBusInFull) {
    auto client = join();
    constexpr std::uint32_t kBurst = 300; // far more than a controller's transmit queue
    std::string burst;
    for (std::uint32_t id = 1; id <= kBurst; ++id) {
        burst += fmt::format("< send {:X} 1 {:02X} >", id, id & 0xFF);
    }
    client->send(burst);
    ASSERT_TRUE(run_until([&] { return node_received.size() == kBurst; }))
        << node_received.size() << " of " << kBurst;
    for (std::uint32_t id = 1; id <= kBurst; ++id) {
        EXPECT_EQ(node_received[id - 1].id, id);
    }
}

// python-can 4.1 wants each handshake reply alone in one recv(): on a busy bus the reply to
// `< rawmode >` must not share a read with the first frames (they follow it a moment later).
TEST_F(SocketcandServerTest, OnABusyBusTheRawModeReplyArrivesAloneAndTheFramesFollow) {
    const core::TimerId traffic = loop.every(
        std::chrono::microseconds(200), [this] { node->send(Frame::data_frame(0x181, {0x01})); });
    auto client = connect();
    ASSERT_TRUE(run_until([&] { return client->messages().size() >= 1; }));
    // A slow client: the read in progress takes the reply to `open`, and it reads again only
    // 5 ms after asking for raw mode, when whatever the server sent by then arrives at once.
    client->stop_reading();
    client->send("< open can0 >");
    ASSERT_TRUE(run_until([&] { return client->messages().size() >= 2; }));
    client->send("< rawmode >");
    loop.run_for(std::chrono::milliseconds(5));
    const std::size_t reads_before = client->reads().size();
    client->start_reading();
    ASSERT_TRUE(run_until([&] { return client->reads().size() > reads_before; }));
    EXPECT_EQ(client->reads()[reads_before], "< ok >");
    ASSERT_TRUE(run_until([&] { return client->messages().size() >= 10; }));
    loop.cancel(traffic);
    EXPECT_EQ(client->frames().front(), Frame::data_frame(0x181, {0x01}));
}

TEST_F(SocketcandServerTest, TwoClientsExchangeFramesThroughTheBus) {
    auto a = join();
    auto b = join();
    const std::vector<std::pair<std::string, Frame>> a_sends = {
        {"< send 000 0 >", Frame::data_frame(0x000, {})},
        {"< send 7FF 1 ff >", Frame::data_frame(0x7FF, {0xFF})},
        {"< send 1ABCDEF0 4 1 2 3 4 >", Frame::data_frame(0x1ABCDEF0, {1, 2, 3, 4}, true)},
        {"< send 1234567 8 0 11 22 33 44 55 66 7 >", // python-can 4.1's extended identifier
         Frame::data_frame(0x1234567, {0, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x07}, true)},
        {"< send 00000012 2 a b >", Frame::data_frame(0x12, {0x0A, 0x0B}, true)},
    };
    for (const auto& [text, frame] : a_sends) {
        a->send(text);
    }
    b->send("< send 321 3 C0 FF EE >");
    ASSERT_TRUE(run_until([&] {
        return b->frames().size() == a_sends.size() && a->frames().size() == 1 &&
               node_received.size() == a_sends.size() + 1;
    }));
    // The bus arbitrates among queued frames by identifier, so only the set is certain.
    for (const auto& [text, frame] : a_sends) {
        EXPECT_EQ(std::ranges::count(b->frames(), frame), 1) << text;
    }
    EXPECT_EQ(a->frames()[0], Frame::data_frame(0x321, {0xC0, 0xFF, 0xEE}));
}

// python-canopen guards a node through python-can 4.1's socketcand interface, which writes the
// guard request (a remote frame) as a frame without data: the node on the bus answers it, with
// the toggle bit alternating (CiA 301 7.2.8.3.2.1).
TEST_F(SocketcandServerTest, AnEmptyFrameOnAGuardingIdentifierGuardsTheNode) {
    const auto slave_port = bus.connect("node 5");
    canopen::ObjectDictionary dictionary;
    canopen::NodeConfig config;
    config.node_id = 5;
    canopen::Node slave(loop, *slave_port, dictionary, config);
    slave.start(); // pre-operational
    auto client = join();
    const auto guard_replies = [&] {
        std::vector<Frame> replies;
        std::ranges::copy_if(client->frames(), std::back_inserter(replies), [](const Frame& f) {
            return f != Frame::data_frame(0x705, {0x00}); // all but the boot-up
        });
        return replies;
    };
    client->send("< send 705 0  >"); // exactly as python-can 4.1 writes it
    ASSERT_TRUE(run_until([&] { return guard_replies().size() == 1; }));
    client->send("< send 705 0  >");
    ASSERT_TRUE(run_until([&] { return guard_replies().size() == 2; }));
    EXPECT_EQ(guard_replies(), (std::vector<Frame>{Frame::data_frame(0x705, {0x7F}),
                                                   Frame::data_frame(0x705, {0xFF})}));
    // The bus carried the guard requests as remote frames.
    EXPECT_EQ(std::ranges::count(node_received, Frame::remote_frame(0x705, 1)), 2);
}

TEST_F(SocketcandServerTest, AnswersEveryOtherCommandAndKeepsTheSession) {
    auto client = join();
    for (const char* command : {"< echo >", "< bcmmode >", "< frobnicate >", "< send 123 9 >",
                                "< add 1 0 123 0 >", "< open can0 >", "< rawmode >"}) {
        client->send(command);
    }
    ASSERT_TRUE(run_until([&] { return client->messages().size() == 10; }));
    const std::vector<std::string> replies(client->messages().begin() + 3,
                                           client->messages().end());
    EXPECT_EQ(replies, (std::vector<std::string>{
                           "< echo >",
                           "< error bcm mode is not supported, only raw mode >",
                           "< error unknown command >",
                           "< error the length must be a digit 0 to 8 >",
                           "< error add is not supported, only raw mode >",
                           "< error a bus is already open >",
                           "< ok >",
                       }));
    client->send("< send 100 0 >");
    ASSERT_TRUE(run_until([&] { return node_received.size() == 1; }));
    EXPECT_FALSE(client->closed());
}

TEST_F(SocketcandServerTest, CommandsBeforeOpenAreRefused) {
    auto client = connect();
    client->send("< send 123 0 >< rawmode >< echo >");
    ASSERT_TRUE(run_until([&] { return client->messages().size() == 4; }));
    EXPECT_EQ(client->messages()[1], "< error open a bus first >");
    EXPECT_EQ(client->messages()[2], "< error open a bus first >");
    EXPECT_EQ(client->messages()[3], "< echo >");
    EXPECT_TRUE(node_received.empty());
}

TEST_F(SocketcandServerTest, WrongBusNameIsRefusedAndTheConnectionClosed) {
    auto client = connect();
    client->send("< open can1 >");
    ASSERT_TRUE(run_until([&] { return client->closed(); }));
    EXPECT_EQ(client->messages(),
              (std::vector<std::string>{
                  "< hi >", "< error could not open bus can1: this server has can0 >"}));
    ASSERT_TRUE(run_until([&] { return server->client_count() == 0; }));
    EXPECT_TRUE(dropped("it asked for bus 'can1', not 'can0'"));
}

TEST_F(SocketcandServerTest, GarbageClosesThatSessionAndTheServerServesOthers) {
    auto good = join();
    auto garbage = connect();
    auto oversize = connect();
    garbage->send("< open can0 >hello\n");
    oversize->send("< open can0 ><" + std::string(500, 'x') + ">");
    ASSERT_TRUE(run_until([&] { return garbage->closed() && oversize->closed(); }));
    EXPECT_EQ(garbage->messages().back(), "< error garbage outside a message >");
    EXPECT_EQ(oversize->messages().back(), "< error message too long >");
    ASSERT_TRUE(run_until([&] { return server->client_count() == 1; }));
    EXPECT_TRUE(left("it sent bytes outside a < > message"));
    EXPECT_TRUE(left("it sent a message longer than 128 bytes"));

    ASSERT_EQ(node->send(Frame::data_frame(0x222, {0x22})), SendStatus::Queued);
    ASSERT_TRUE(run_until([&] { return good->frames().size() == 1; }));
    EXPECT_EQ(good->frames()[0], Frame::data_frame(0x222, {0x22}));
}

TEST_F(SocketcandServerTest, DisconnectDetachesThePort) {
    auto leaving = join();
    auto staying = join();
    ASSERT_EQ(server->clients().size(), 2U);
    leaving->disconnect();
    ASSERT_TRUE(run_until([&] { return server->client_count() == 1; }));
    EXPECT_TRUE(left("the client disconnected"));
    const auto clients = server->clients();
    ASSERT_EQ(clients.size(), 1U);
    EXPECT_EQ(clients[0].client, "socketcand-2");

    staying->send("< send 010 1 01 >");
    ASSERT_TRUE(run_until([&] { return node_received.size() == 1; }));
}

// A client that sends faster than its transmit queue drains loses frames: it is told once per
// burst, not once per frame, and what it lost is still counted after it has left.
TEST_F(SocketcandServerTest, AFullTransmitQueueIsAnsweredOncePerBurstAndCountedAfterLeaving) {
    start_server({.limits = {.tx_queue_capacity = 4}});
    auto client = join();
    constexpr std::size_t kBurst = 20;
    std::string burst;
    for (std::size_t i = 0; i < kBurst; ++i) {
        burst += fmt::format("< send {:03X} 0 >", 0x100 + i);
    }
    const auto refused = [&] {
        const auto clients = server->clients();
        return clients.size() == 1 && clients[0].port ? clients[0].port->tx_overflows : 0U;
    };
    for (std::size_t sent = kBurst; sent <= 2 * kBurst; sent += kBurst) {
        client->send(burst); // one TCP write, parsed at once: the bus cannot drain meanwhile
        ASSERT_TRUE(run_until([&] { return node_received.size() + refused() == sent; }));
    }
    const std::vector<std::string> replies(client->messages().begin() + 3,
                                           client->messages().end());
    EXPECT_EQ(replies, std::vector<std::string>(
                           2, "< error frame not sent: transmit queue full; the following ones "
                              "are dropped without a reply until one is sent >"));
    const std::uint64_t lost = refused();
    EXPECT_GT(lost, 0U);

    client->disconnect();
    ASSERT_TRUE(run_until([&] { return server->client_count() == 0; }));
    const SocketcandServerStatistics statistics = server->statistics();
    EXPECT_EQ(statistics.left, 1U);
    EXPECT_EQ(statistics.left_tx_overflows, lost);
    EXPECT_EQ(statistics.left_tx_frames, node_received.size());
}

// A script that sends and hangs up at once: what it sent still goes on the bus, and its port
// leaves once it has.
TEST_F(SocketcandServerTest, FramesOfAClientThatHangsUpAreSentBeforeItsPortLeaves) {
    auto client = join();
    constexpr std::size_t kBurst = 100; // 5 ms of bus time at 1 Mbit/s
    std::string burst;
    for (std::size_t i = 0; i < kBurst; ++i) {
        burst += fmt::format("< send {:03X} 1 {:02X} >", 0x100 + i, i);
    }
    client->send(burst);
    ASSERT_TRUE(run_until([&] { return !node_received.empty(); }));
    client->disconnect(); // with most of the burst still queued
    ASSERT_TRUE(run_until([&] { return server->client_count() == 0; }));
    EXPECT_EQ(node_received.size(), kBurst);
    EXPECT_TRUE(left("the client disconnected"));
    EXPECT_EQ(server->statistics().left_tx_frames, kBurst);
}

// "joined" means a port on the bus: a connection that has only been greeted is not a client yet.
TEST_F(SocketcandServerTest, AClientJoinsWhenItOpensTheBusNotWhenItConnects) {
    auto client = connect();
    ASSERT_TRUE(run_until([&] { return client->messages().size() == 1; }));
    EXPECT_TRUE(events.empty());
    EXPECT_EQ(server->client_count(), 1U);
    client->send("< open can0 >");
    ASSERT_TRUE(run_until([&] { return !events.empty(); }));
    EXPECT_EQ(events[0].kind, SocketcandClientEvent::Kind::Joined);
    EXPECT_EQ(server->statistics().joined, 1U);
}

// An idle connection holds a file descriptor: one that does not open the bus in time is let go,
// one that did stays however quiet it is.
TEST_F(SocketcandServerTest, AConnectionThatDoesNotOpenTheBusInTimeIsDropped) {
    start_server({.limits = {.open_timeout = std::chrono::milliseconds(100)}});
    auto member = join();
    auto idle = connect();
    ASSERT_TRUE(run_until([&] { return idle->closed(); }));
    EXPECT_EQ(idle->messages(),
              (std::vector<std::string>{"< hi >", "< error no bus opened within 100ms >"}));
    EXPECT_TRUE(dropped("it did not open a bus within 100ms"));
    EXPECT_EQ(server->statistics().dropped, 1U);

    ASSERT_EQ(node->send(Frame::data_frame(0x123, {})), SendStatus::Queued);
    ASSERT_TRUE(run_until([&] { return member->frames().size() == 1; }));
    EXPECT_FALSE(member->closed());
    EXPECT_EQ(server->client_count(), 1U);
}

TEST_F(SocketcandServerTest, ConnectionsBeyondTheLimitAreTurnedAway) {
    start_server({.limits = {.max_clients = 2}});
    auto first = join();
    auto second = connect(); // counts before it has opened the bus
    ASSERT_TRUE(run_until([&] { return second->messages().size() == 1; }));
    auto third = connect();
    ASSERT_TRUE(run_until([&] { return third->closed(); }));
    EXPECT_EQ(third->messages(), (std::vector<std::string>{"< error too many clients >"}));
    EXPECT_TRUE(dropped("2 clients are connected already"));
    EXPECT_EQ(server->statistics().turned_away, 1U);

    first->disconnect();
    ASSERT_TRUE(run_until([&] { return server->client_count() == 1; }));
    auto fourth = connect();
    ASSERT_TRUE(run_until([&] { return fourth->messages().size() == 1; }));
    EXPECT_EQ(fourth->messages()[0], "< hi >");
}

TEST_F(SocketcandServerTest, ASlowClientIsPausedAndCountsOverflowsInsteadOfGrowing) {
    start_server(
        {.pause_above_bytes = 2048, .resume_below_bytes = 512, .socket_send_buffer_bytes = 4096});
    auto slow = join(2048); // a small kernel buffer, so that the server's queue fills soon
    slow->stop_reading();

    // Keep the node's transmit queue full: one more frame whenever one has passed the wire.
    bool flooding = true;
    std::uint32_t sent = 0;
    const auto send_one = [&] {
        return node->send(Frame::data_frame(sent++ & 0x3FF, {}));
    };
    while (send_one() == SendStatus::Queued) {
    }
    bool marker_sent = false;
    const auto observer = bus.add_observer([&](const WireEvent&) {
        if (flooding) {
            send_one();
        } else if (!marker_sent) {
            marker_sent = node->send(Frame::data_frame(0x7AB, {0xAB})) == SendStatus::Queued;
        }
        progress();
    });
    const auto overflows = [&] {
        const auto clients = server->clients();
        return clients.size() == 1 && clients[0].port && clients[0].port->rx_overflows > 0;
    };
    ASSERT_TRUE(run_until(overflows));
    flooding = false;

    // Once it reads again it catches up and receives what the bus carries from then on.
    slow->start_reading();
    ASSERT_TRUE(run_until([&] { return marker_sent; }));
    ASSERT_TRUE(run_until([&] { return slow->messages().back().starts_with("< frame 7AB "); }));
    EXPECT_EQ(slow->frames().back(), Frame::data_frame(0x7AB, {0xAB}));
    bus.remove_observer(observer);
    EXPECT_FALSE(slow->closed());
}

} // namespace
} // namespace eposp::can::io
