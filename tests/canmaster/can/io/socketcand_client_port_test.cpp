// The socketcand client port: parsing what a server sends, then the port over real loopback TCP
// against our own SocketcandServer and against scripted servers that misbehave. The loop runs in
// real time with everything on its io_context; each wait is bounded by a deadline and ends as
// soon as what it waits for has happened.
#include "eposp/can/io/socketcand_client_port.hpp"
#include "eposp/can/io/socketcand_protocol.hpp"
#include "eposp/can/io/socketcand_server.hpp"

#include <algorithm>
#include <array>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <ostream>

namespace eposp::can::io {
namespace {

using namespace std::chrono_literals;
using boost::asio::ip::tcp;
using testing::HasSubstr;
using Event = SocketcandClientPort::Event;

constexpr core::Duration kDeadline = 5s;

Frame extended_frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
    return Frame::data_frame(id, bytes, true);
}

// ---- parse_server_message ---------------------------------------------------------------------

struct ServerFrameCase {
    std::string_view message;
    Frame expected;
    core::Duration since_epoch;
    friend void PrintTo(const ServerFrameCase& c, std::ostream* os) { *os << c.message; }
};

class ParseServerFrame : public testing::TestWithParam<ServerFrameCase> {};

TEST_P(ParseServerFrame, GivesTheFrameAndItsTime) {
    const auto message = socketcand::parse_server_message(GetParam().message);
    const auto* received = std::get_if<socketcand::ReceivedFrame>(&message);
    ASSERT_NE(received, nullptr) << GetParam().message;
    EXPECT_EQ(received->frame, GetParam().expected);
    EXPECT_EQ(received->since_epoch, GetParam().since_epoch);
}

INSTANTIATE_TEST_SUITE_P(
    Table, ParseServerFrame,
    testing::Values(
        // as socketcand writes them (state_raw.c: `%03X` / `%08X`, `%ld.%06ld`, `%02X` each)
        ServerFrameCase{"< frame 123 23.424242 11223344 >",
                        Frame::data_frame(0x123, {0x11, 0x22, 0x33, 0x44}), 23s + 424242us},
        ServerFrameCase{"< frame 005 1.000000  >", Frame::data_frame(0x5, {}), 1s},
        ServerFrameCase{"< frame 7FF 1700000000.000007 00010203040506FF >",
                        Frame::data_frame(0x7FF, {0, 1, 2, 3, 4, 5, 6, 0xFF}),
                        1'700'000'000s + 7us},
        ServerFrameCase{"< frame 00000123 0.000000 AB >", extended_frame(0x123, {0xAB}), 0s},
        ServerFrameCase{"< frame 1FFFFFFF 2.000000  >", extended_frame(0x1FFFFFFF, {}), 2s},
        // tolerated: one space before '>' when empty, lower case, a short fraction, an
        // extended identifier without leading zeros
        ServerFrameCase{"< frame 005 1.000000 >", Frame::data_frame(0x5, {}), 1s},
        ServerFrameCase{"<frame 1234567 1.5 ab>", extended_frame(0x1234567, {0xAB}), 1500ms},
        // our server's remote and error frames
        ServerFrameCase{"< rtr 123 23.424242 4 >", Frame::remote_frame(0x123, 4), 23s + 424242us},
        ServerFrameCase{"< rtr 00000123 1.000000 0 >", Frame::remote_frame(0x123, 0, true), 1s},
        ServerFrameCase{"< error 040 3.500000 >", Frame{.id = 0x40, .error = true, .dlc = 8},
                        3s + 500ms}));

class ParseServerMalformed : public testing::TestWithParam<std::string_view> {};

TEST_P(ParseServerMalformed, SaysWhatIsWrong) {
    const auto message = socketcand::parse_server_message(GetParam());
    const auto* malformed = std::get_if<socketcand::Malformed>(&message);
    ASSERT_NE(malformed, nullptr) << GetParam();
    EXPECT_FALSE(malformed->reason.empty());
}

INSTANTIATE_TEST_SUITE_P(Table, ParseServerMalformed,
                         testing::Values("", "hi", "< >", "< hi there >", "< ok 1 >", "< frame >",
                                         "< frame 123 >",                        // too short
                                         "< frame 123 1.0 AB CD >",              // bytes spaced
                                         "< frame 12G 1.0 AB >",                 // id not hex
                                         "< frame 20000000 1.0 AB >",            // beyond 29 bits
                                         "< frame 123 1.0 ABC >",                // half a byte
                                         "< frame 123 1.0 001122334455667788 >", // nine bytes
                                         "< frame 123 1.0 GG >",                 // byte not hex
                                         "< frame 123 x AB >", "< frame 123 1. AB >",
                                         "< frame 123 .5 AB >", "< frame 123 1.1234567 AB >",
                                         "< frame 123 -1.0 AB >", "< rtr 123 1.0 >",
                                         "< rtr 123 1.0 9 >"));

TEST(SocketcandParseServer, GreetingsRepliesAndUnknownMessages) {
    using namespace socketcand;
    EXPECT_TRUE(std::holds_alternative<Hi>(parse_server_message("< hi >")));
    EXPECT_TRUE(std::holds_alternative<Ok>(parse_server_message("<ok>")));
    EXPECT_TRUE(std::holds_alternative<Echo>(parse_server_message("< echo >")));
    for (const auto& [text, reason] :
         {std::pair{"< error could not open bus >", "could not open bus"},
          std::pair{"<  error  unknown  command >", "unknown  command"},
          std::pair{"< error 040 now >", "040 now"}, // no time stamp: not an error frame
          std::pair{"< error >", ""}}) {
        const auto message = parse_server_message(text);
        ASSERT_TRUE(std::holds_alternative<ErrorReply>(message)) << text;
        EXPECT_EQ(std::get<ErrorReply>(message).reason, reason) << text;
    }
    const auto fd = parse_server_message("< fdframe 123 00 1.000000 AB >");
    ASSERT_TRUE(std::holds_alternative<Unknown>(fd));
    EXPECT_EQ(std::get<Unknown>(fd).name, "fdframe");
}

TEST(SocketcandParseServer, ReadsBackWhatOurServerWrites) {
    std::vector<Frame> frames = {Frame::remote_frame(0x701, 1), Frame::remote_frame(0x100, 8, true),
                                 Frame{.id = 0x4, .error = true, .dlc = 8}};
    const std::array<std::uint8_t, 8> bytes{0xDE, 0xAD, 0xBE, 0xEF, 0x00, 0x01, 0x7F, 0x80};
    for (std::uint32_t n = 0; n <= bytes.size(); ++n) {
        frames.push_back(Frame::data_frame(0x7FF - n, std::span(bytes.data(), n)));
        frames.push_back(Frame::data_frame(0x1FFFFFF0 + n, std::span(bytes.data(), n), true));
    }
    for (const Frame& frame : frames) {
        const std::string text = socketcand::format_received(frame, 1'700'000'000s + 123456us);
        const auto message = socketcand::parse_server_message(text);
        ASSERT_TRUE(std::holds_alternative<socketcand::ReceivedFrame>(message)) << text;
        EXPECT_EQ(std::get<socketcand::ReceivedFrame>(message).frame, frame) << text;
        EXPECT_EQ(std::get<socketcand::ReceivedFrame>(message).since_epoch,
                  1'700'000'000s + 123456us)
            << text;
    }
}

// ---- The port ---------------------------------------------------------------------------------

/// A server of its own: accepts one client, writes `script` to it at once (then ends its side
/// of the connection when asked to) and records what the client sends.
class ScriptedServer {
public:
    ScriptedServer(core::EventLoop& loop, std::string script, bool close_after_script,
                   std::function<void()> on_progress)
        : acceptor_(loop.io(), {boost::asio::ip::make_address_v4("127.0.0.1"), 0}),
          socket_(loop.io()), script_(std::move(script)), close_after_script_(close_after_script),
          on_progress_(std::move(on_progress)) {
        acceptor_.async_accept(socket_, [this](boost::system::error_code error) {
            if (error) {
                return;
            }
            boost::asio::async_write(socket_, boost::asio::buffer(script_),
                                     [this](boost::system::error_code, std::size_t) {
                                         if (close_after_script_) {
                                             // FIN, not RST: it still reads what comes
                                             boost::system::error_code ignored;
                                             socket_.shutdown(tcp::socket::shutdown_send, ignored);
                                         }
                                     });
            read();
        });
    }

    std::string address() const {
        return "127.0.0.1:" + std::to_string(acceptor_.local_endpoint().port());
    }
    const std::string& received() const { return received_; }

private:
    void read() {
        socket_.async_read_some(boost::asio::buffer(buffer_),
                                [this](boost::system::error_code error, std::size_t size) {
                                    if (error) {
                                        return;
                                    }
                                    received_.append(buffer_.data(), size);
                                    on_progress_();
                                    read();
                                });
    }

    tcp::acceptor acceptor_;
    tcp::socket socket_;
    std::string script_;
    bool close_after_script_;
    std::function<void()> on_progress_;
    std::array<char, 1024> buffer_{};
    std::string received_;
};

class SocketcandClientPortTest : public testing::Test {
protected:
    void SetUp() override {
        auto opened = SocketcandServer::open(bus, {.listen = "127.0.0.1:0"});
        ASSERT_TRUE(opened) << opened.error();
        server = std::move(*opened);
        node->on_receive([this](const Frame& frame) {
            node_received.push_back(frame);
            progress();
        });
    }

    /// Opens a port to `address` that records its events and frames.
    std::unique_ptr<SocketcandClientPort> open(const std::string& address,
                                               const std::string& bus_name = "can0") {
        auto opened = SocketcandClientPort::open(loop, address, bus_name);
        EXPECT_TRUE(opened) << opened.error();
        if (!opened) {
            return nullptr;
        }
        auto port = std::move(*opened);
        port->on_event([this](const Event& event) {
            events.push_back(event);
            progress();
        });
        port->on_receive([this](const Frame& frame) {
            port_received.push_back(frame);
            progress();
        });
        return port;
    }

    std::unique_ptr<SocketcandClientPort> join() {
        auto port = open(server->address());
        EXPECT_TRUE(run_until([&] { return port->connected(); }));
        return port;
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

    bool failed() const {
        return std::ranges::any_of(events,
                                   [](const Event& e) { return e.kind == Event::Kind::Failed; });
    }
    std::string failure_text() const {
        const auto it = std::ranges::find_if(
            events, [](const Event& e) { return e.kind == Event::Kind::Failed; });
        return it == events.end() ? std::string() : it->text;
    }

    core::EventLoop loop{core::Pace::RealTime};
    VirtualBus bus{loop, BusConfig{.name = "can0"}};
    std::unique_ptr<VirtualPort> node = bus.connect("node");
    std::vector<Frame> node_received;
    std::unique_ptr<SocketcandServer> server;
    std::vector<Event> events;
    std::vector<Frame> port_received;

private:
    std::function<bool()> waiting_for_;
};

TEST_F(SocketcandClientPortTest, JoinsTheServedBusAndCarriesFramesBothWays) {
    auto port = join();
    ASSERT_TRUE(port->connected());
    EXPECT_EQ(server->client_count(), 1U);
    ASSERT_EQ(events.size(), 1U);
    EXPECT_EQ(events[0].kind, Event::Kind::Connected);
    EXPECT_EQ(port->name(), server->address() + " can0");

    // Every length, both identifier formats and remote frames, each way.
    std::vector<Frame> frames = {Frame::remote_frame(0x701, 1),
                                 Frame::remote_frame(0x1ABCDEF, 8, true),
                                 extended_frame(0x00000012, {0x0A, 0x0B})};
    const std::array<std::uint8_t, 8> bytes{0x00, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0xFF};
    for (std::uint32_t n = 0; n <= bytes.size(); ++n) {
        frames.push_back(Frame::data_frame(0x100 + n, std::span(bytes.data(), n)));
        frames.push_back(Frame::data_frame(0x1FFFFFF0 + n, std::span(bytes.data(), n), true));
    }
    for (const Frame& frame : frames) {
        ASSERT_EQ(port->send(frame), SendStatus::Queued);
    }
    ASSERT_TRUE(run_until([&] { return node_received.size() == frames.size(); }));
    for (const Frame& frame : frames) {
        ASSERT_EQ(node->send(frame), SendStatus::Queued);
    }
    ASSERT_TRUE(run_until([&] { return port_received.size() == frames.size(); }));
    // The bus arbitrates among queued frames by identifier, so only the set is certain.
    for (const Frame& frame : frames) {
        EXPECT_EQ(std::ranges::count(node_received, frame), 1);
        EXPECT_EQ(std::ranges::count(port_received, frame), 1);
    }
    EXPECT_EQ(port->send(Frame::data_frame(0x800, {})), SendStatus::InvalidFrame);
    EXPECT_EQ(events.size(), 1U);
}

TEST_F(SocketcandClientPortTest, FramesSentWhileConnectingGoOutOnceRawModeIsOn) {
    auto port = open(server->address());
    EXPECT_FALSE(port->connected());
    ASSERT_EQ(port->send(Frame::data_frame(0x181, {0x01})), SendStatus::Queued);
    ASSERT_TRUE(run_until([&] { return node_received.size() == 1; }));
    EXPECT_EQ(node_received[0], Frame::data_frame(0x181, {0x01}));
    EXPECT_TRUE(port->connected());
}

TEST_F(SocketcandClientPortTest, TwoPortsMeetOnTheServedBus) {
    auto a = join();
    auto b = join();
    std::vector<Frame> b_received;
    b->on_receive([&](const Frame& frame) {
        b_received.push_back(frame);
        progress();
    });
    ASSERT_EQ(a->send(extended_frame(0x18FF0001, {1, 2, 3})), SendStatus::Queued);
    ASSERT_TRUE(run_until([&] { return b_received.size() == 1 && node_received.size() == 1; }));
    EXPECT_EQ(b_received[0], extended_frame(0x18FF0001, {1, 2, 3}));
    EXPECT_TRUE(port_received.empty()); // a does not receive its own frame
}

TEST_F(SocketcandClientPortTest, AWrongBusNameFailsWithTheServersReason) {
    auto port = open(server->address(), "can1");
    ASSERT_TRUE(run_until([&] { return failed(); }));
    EXPECT_THAT(failure_text(), HasSubstr("refused to open bus can1"));
    EXPECT_THAT(failure_text(), HasSubstr("this server has can0"));
    EXPECT_EQ(port->failure(), failure_text());
    EXPECT_FALSE(port->connected());
    EXPECT_EQ(port->send(Frame::data_frame(0x123, {})), SendStatus::Disconnected);
}

TEST_F(SocketcandClientPortTest, ARefusedConnectionFailsClearly) {
    // A port that was free a moment ago: nothing listens there now.
    std::uint16_t free_port = 0;
    {
        tcp::acceptor probe(loop.io(), {boost::asio::ip::make_address_v4("127.0.0.1"), 0});
        free_port = probe.local_endpoint().port();
    }
    const std::string address = "127.0.0.1:" + std::to_string(free_port);
    auto port = open(address);
    ASSERT_TRUE(run_until([&] { return failed(); }));
    EXPECT_EQ(failure_text(), "cannot connect to " + address + ": Connection refused");
    EXPECT_EQ(port->send(Frame::data_frame(0x123, {})), SendStatus::Disconnected);
    EXPECT_EQ(events.size(), 1U);
}

TEST_F(SocketcandClientPortTest, BadAddressesAndBusNamesAreRefusedAtOpen) {
    for (const char* address : {"nonsense", "127.0.0.1:", "127.0.0.1:99999", "::1:80", ""}) {
        const auto opened = SocketcandClientPort::open(loop, address, "can0");
        ASSERT_FALSE(opened) << address;
        EXPECT_THAT(opened.error(), HasSubstr("not an address to connect to")) << address;
    }
    for (const char* name : {"", "can 0", "abcdefghijklmnopq", "a>b"}) {
        const auto opened = SocketcandClientPort::open(loop, server->address(), name);
        ASSERT_FALSE(opened) << name;
        EXPECT_THAT(opened.error(), HasSubstr("not a socketcand bus name")) << name;
    }
}

TEST_F(SocketcandClientPortTest, TheServerGoingAwayIsReported) {
    auto port = join();
    const std::string address = server->address();
    server.reset();
    ASSERT_TRUE(run_until([&] { return failed(); }));
    EXPECT_EQ(failure_text(), address + " closed the connection");
    EXPECT_EQ(port->send(Frame::data_frame(0x123, {})), SendStatus::Disconnected);
}

TEST_F(SocketcandClientPortTest, MisbehavingServersFailTheConnectionWithTheReason) {
    struct Case {
        std::string script;
        bool close_after_script;
        std::string reason;
    };
    const std::vector<Case> cases = {
        {"< hi >< error x >", false, "refused to open bus can0: x"},
        {"< hi >< ok >< error no raw mode here >", false, "refused raw mode on bus can0: no raw"},
        {"< hi >hello", false, "sent bytes outside a < > message"},
        {"< hi ><" + std::string(200, 'x'), false, "sent a message longer than 128 bytes"},
        {"< hi >< ok >< ok >< frame 12G 1.000000 AB >", false, "sent a malformed message"},
        {"< hi >< ok >< hi >", false, "sent < hi > out of turn"},
        {"< hi >< ok >< ok >< ok >", false, "sent < ok > out of turn"},
        {"", true, "closed the connection"},
        {"< hi >< ok >", true, "closed the connection"},
    };
    for (const Case& c : cases) {
        events.clear();
        ScriptedServer scripted(loop, c.script, c.close_after_script, [this] { progress(); });
        auto port = open(scripted.address());
        ASSERT_TRUE(run_until([&] { return failed(); })) << c.script;
        EXPECT_THAT(failure_text(), HasSubstr(scripted.address() + " ")) << c.script;
        EXPECT_THAT(failure_text(), HasSubstr(c.reason)) << c.script;
        EXPECT_EQ(port->failure(), failure_text());
        EXPECT_EQ(std::ranges::count_if(
                      events, [](const Event& e) { return e.kind == Event::Kind::Failed; }),
                  1)
            << c.script;
    }
}

TEST_F(SocketcandClientPortTest, ErrorRepliesInRawModeAreReportedAndTheLinkStays) {
    ScriptedServer scripted(loop,
                            "< hi >\n< ok >\n< ok >\n< error unknown command >"
                            "< frame 123 1.000000 AB >< fdframe 123 00 1.000000 AB >"
                            "< echo >< frame 00000456 1.000001  >",
                            false, [this] { progress(); });
    auto port = open(scripted.address());
    ASSERT_TRUE(run_until([&] { return port_received.size() == 2; }));
    EXPECT_EQ(port_received[0], Frame::data_frame(0x123, {0xAB}));
    EXPECT_EQ(port_received[1], extended_frame(0x456, {}));
    ASSERT_EQ(events.size(), 2U);
    EXPECT_EQ(events[0].kind, Event::Kind::Connected);
    EXPECT_EQ(events[1].kind, Event::Kind::ServerError);
    EXPECT_EQ(events[1].text, scripted.address() + " answered: unknown command");
    EXPECT_TRUE(port->connected());

    // The handshake exactly as socketcand expects it, then the frame.
    ASSERT_EQ(port->send(Frame::data_frame(0x7FF, {0x01, 0x02})), SendStatus::Queued);
    const std::string expected = "< open can0 >< rawmode >< send 7FF 2 01 02 >";
    ASSERT_TRUE(run_until([&] { return scripted.received().size() >= expected.size(); }));
    EXPECT_EQ(scripted.received(), expected);
}

TEST_F(SocketcandClientPortTest, TheEventHandlerMayDestroyThePort) {
    ScriptedServer scripted(loop, "< hi >< error go away >", false, [this] { progress(); });
    auto port = open(scripted.address());
    std::string reason;
    port->on_event([&](const Event& event) {
        reason = event.text;
        port.reset();
        progress();
    });
    ASSERT_TRUE(run_until([&] { return !port; }));
    EXPECT_THAT(reason, HasSubstr("go away"));
}

} // namespace
} // namespace eposp::can::io
