#include "eposp/can/io/socketcand_protocol.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <ostream>

namespace eposp::can::io::socketcand {
namespace {

using namespace std::chrono_literals;

Frame extended_frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
    return Frame::data_frame(id, bytes, true);
}

// ---- parse_command ----------------------------------------------------------------------------

struct SendCase {
    std::string_view message;
    Frame expected;
    friend void PrintTo(const SendCase& c, std::ostream* os) { *os << c.message; }
};

class ParseSend : public testing::TestWithParam<SendCase> {};

TEST_P(ParseSend, GivesTheFrame) {
    const Command command = parse_command(GetParam().message);
    const auto* send = std::get_if<SendFrame>(&command);
    ASSERT_NE(send, nullptr) << GetParam().message;
    EXPECT_EQ(send->frame, GetParam().expected) << GetParam().message;
}

INSTANTIATE_TEST_SUITE_P(
    Table, ParseSend,
    testing::Values(
        // socketcand's own examples (doc/protocol.md)
        SendCase{"< send 123 0 >", Frame::data_frame(0x123, {})},
        SendCase{"< send 1AAAAAAA 2 1 F1 >", extended_frame(0x1AAAAAAA, {0x01, 0xF1})},
        // every length, upper and lower case
        SendCase{"< send 7FF 1 ff >", Frame::data_frame(0x7FF, {0xFF})},
        SendCase{"< send 000 3 00 01 02 >", Frame::data_frame(0x000, {0, 1, 2})},
        SendCase{"< send 181 8 11 22 33 44 55 66 77 88 >",
                 Frame::data_frame(0x181, {0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88})},
        // an 8-digit identifier is extended even when its value fits 11 bits
        SendCase{"< send 00000123 1 AA >", extended_frame(0x123, {0xAA})},
        SendCase{"< send 1FFFFFFF 0 >", extended_frame(0x1FFFFFFF, {})},
        // python-can 4.1: identifier without leading zeros, DLC in hex, bytes as `{:x}`, and
        // two spaces when there are no bytes
        SendCase{"< send 1234567 4 de ad b e >", extended_frame(0x1234567, {0xDE, 0xAD, 0xB, 0xE})},
        SendCase{"< send 12 0  >", Frame::data_frame(0x12, {})},
        SendCase{"< send 800 2 0 a >", extended_frame(0x800, {0x00, 0x0A})},
        // fewer than 8 digits: standard up to 7FF however many leading zeros, extended beyond
        SendCase{"< send 00007FF 0 >", Frame::data_frame(0x7FF, {})},
        SendCase{"< send 0800 0 >", extended_frame(0x800, {})},
        // extra whitespace and newlines are tolerated
        SendCase{"<send 100 1 5>", Frame::data_frame(0x100, {0x05})},
        SendCase{"<  send\t100  2 5 6\r\n>", Frame::data_frame(0x100, {0x05, 0x06})},
        // remote frames
        SendCase{"< sendrtr 123 0 >", Frame::remote_frame(0x123, 0)},
        SendCase{"< sendrtr 1AAAAAAA 2 >", Frame::remote_frame(0x1AAAAAAA, 2, true)}));

// ---- frame_for_bus ----------------------------------------------------------------------------

struct BusFrameCase {
    Frame sent;
    Frame on_bus;
    friend void PrintTo(const BusFrameCase& c, std::ostream* os) { *os << format_send(c.sent); }
};

class FrameForBus : public testing::TestWithParam<BusFrameCase> {};

TEST_P(FrameForBus, TakesOnlyAnEmptyFrameOnAGuardingIdentifierForTheGuardRequest) {
    EXPECT_EQ(frame_for_bus(GetParam().sent), GetParam().on_bus);
}

INSTANTIATE_TEST_SUITE_P(
    Table, FrameForBus,
    testing::Values(
        // python-can 4.1's node guard request for nodes 1, 5 and 127 (CiA 301 7.2.8.3.2.1)
        BusFrameCase{Frame::data_frame(0x701, {}), Frame::remote_frame(0x701, 1)},
        BusFrameCase{Frame::data_frame(0x705, {}), Frame::remote_frame(0x705, 1)},
        BusFrameCase{Frame::data_frame(0x77F, {}), Frame::remote_frame(0x77F, 1)},
        // boot-up and heartbeat carry a byte; 0x700 and 0x780 are no node's; extended frames
        // and remote frames are as sent
        BusFrameCase{Frame::data_frame(0x705, {0x00}), Frame::data_frame(0x705, {0x00})},
        BusFrameCase{Frame::data_frame(0x700, {}), Frame::data_frame(0x700, {})},
        BusFrameCase{Frame::data_frame(0x780, {}), Frame::data_frame(0x780, {})},
        BusFrameCase{extended_frame(0x705, {}), extended_frame(0x705, {})},
        BusFrameCase{Frame::remote_frame(0x705, 0), Frame::remote_frame(0x705, 0)}));

class ParseMalformed : public testing::TestWithParam<std::string_view> {};

TEST_P(ParseMalformed, SaysWhatIsWrong) {
    const Command command = parse_command(GetParam());
    const auto* malformed = std::get_if<Malformed>(&command);
    ASSERT_NE(malformed, nullptr) << GetParam();
    EXPECT_FALSE(malformed->reason.empty());
}

INSTANTIATE_TEST_SUITE_P(Table, ParseMalformed,
                         testing::Values("", "<", ">", "send 123 0", "< >", "<>",
                                         "< send >",                         // no id, no length
                                         "< send 123 >",                     // no length
                                         "< send xyz 0 >",                   // id not hex
                                         "< send -12 0 >",                   // signed
                                         "< send 0x12 0 >",                  // prefix
                                         "< send 123456789 0 >",             // 9 digits
                                         "< send 20000000 0 >",              // beyond 29 bits
                                         "< send 123 9 1 2 3 4 5 6 7 8 9 >", // DLC 9
                                         "< send 123 2 11 >",                // fewer bytes than DLC
                                         "< send 123 1 11 22 >",             // more bytes than DLC
                                         "< send 123 1 123 >",               // 3-digit byte
                                         "< send 123 1 g >",                 // byte not hex
                                         "< send 123 A >",                   // DLC 10 in hex
                                         "< send 123 01 1 >",                // DLC two digits
                                         "< sendrtr 123 1 AA >",             // RTR with data
                                         "< open >", "< open a b >",
                                         "< open abcdefghijklmnopq >", // 17 characters
                                         "< rawmode now >", "< echo echo >"));

TEST(SocketcandParse, OpenNamesTheBus) {
    const Command command = parse_command("< open can0 >");
    ASSERT_TRUE(std::holds_alternative<OpenBus>(command));
    EXPECT_EQ(std::get<OpenBus>(command).bus, "can0");
}

TEST(SocketcandParse, ModeSwitches) {
    for (const auto& [text, mode] :
         {std::pair{"< rawmode >", Mode::Raw}, std::pair{"< bcmmode >", Mode::Bcm},
          std::pair{"< controlmode >", Mode::Control}, std::pair{"< isotpmode >", Mode::IsoTp}}) {
        const Command command = parse_command(text);
        ASSERT_TRUE(std::holds_alternative<SwitchMode>(command)) << text;
        EXPECT_EQ(std::get<SwitchMode>(command).mode, mode) << text;
    }
}

TEST(SocketcandParse, EchoUnsupportedAndUnknown) {
    EXPECT_TRUE(std::holds_alternative<Echo>(parse_command("< echo >")));
    for (const char* text : {"< add 1 0 123 8 11 22 33 44 55 66 77 88 >", "< subscribe 0 0 123 >",
                             "< fdsend 123 0 0 >", "< statistics 1000 >"}) {
        EXPECT_TRUE(std::holds_alternative<NotSupported>(parse_command(text))) << text;
    }
    const Command unknown = parse_command("< frobnicate 1 >");
    ASSERT_TRUE(std::holds_alternative<Unknown>(unknown));
    EXPECT_EQ(std::get<Unknown>(unknown).name, "frobnicate");
}

// ---- scan_message -----------------------------------------------------------------------------

TEST(SocketcandScan, FindsTheFirstMessage) {
    const Scan scan = scan_message("< hi >< ok >");
    EXPECT_EQ(scan.kind, Scan::Kind::Message);
    EXPECT_EQ(scan.message, "< hi >");
    EXPECT_EQ(scan.consumed, 6U);
}

TEST(SocketcandScan, SkipsWhitespaceBetweenMessages) {
    const Scan scan = scan_message(" \r\n\t< echo >\n");
    EXPECT_EQ(scan.kind, Scan::Kind::Message);
    EXPECT_EQ(scan.message, "< echo >");
    EXPECT_EQ(scan.consumed, 12U);
}

TEST(SocketcandScan, WaitsForTheRestOfAMessage) {
    const Scan partial = scan_message("  < send 123 ");
    EXPECT_EQ(partial.kind, Scan::Kind::Incomplete);
    EXPECT_EQ(partial.consumed, 2U); // only the leading whitespace
    EXPECT_EQ(scan_message("").kind, Scan::Kind::Incomplete);
    const Scan blank = scan_message("\n\n");
    EXPECT_EQ(blank.kind, Scan::Kind::Incomplete);
    EXPECT_EQ(blank.consumed, 2U);
}

TEST(SocketcandScan, RejectsGarbage) {
    EXPECT_EQ(scan_message("hello").kind, Scan::Kind::Garbage);
    EXPECT_EQ(scan_message("> < hi >").kind, Scan::Kind::Garbage);
    EXPECT_EQ(scan_message("< send < hi >").kind, Scan::Kind::Garbage);
    EXPECT_EQ(scan_message(std::string_view("\0< hi >", 7)).kind, Scan::Kind::Garbage);
}

TEST(SocketcandScan, RejectsOversizeMessages) {
    const std::string longest = "<" + std::string(kMaxMessageLength - 2, ' ') + ">";
    EXPECT_EQ(scan_message(longest).kind, Scan::Kind::Message);
    const std::string too_long = "<" + std::string(kMaxMessageLength - 1, ' ') + ">";
    EXPECT_EQ(scan_message(too_long).kind, Scan::Kind::TooLong);
    // known to be too long before its end arrives
    EXPECT_EQ(scan_message("<" + std::string(kMaxMessageLength - 1, 'x')).kind,
              Scan::Kind::TooLong);
    EXPECT_EQ(scan_message("<" + std::string(kMaxMessageLength - 2, 'x')).kind,
              Scan::Kind::Incomplete);
}

// ---- formatting -------------------------------------------------------------------------------

struct ReceivedCase {
    Frame frame;
    core::Duration since_epoch;
    std::string_view expected;
    friend void PrintTo(const ReceivedCase& c, std::ostream* os) { *os << c.expected; }
};

class FormatReceived : public testing::TestWithParam<ReceivedCase> {};

TEST_P(FormatReceived, WritesWhatSocketcandWrites) {
    EXPECT_EQ(format_received(GetParam().frame, GetParam().since_epoch), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Table, FormatReceived,
    testing::Values(
        ReceivedCase{Frame::data_frame(0x123, {0x11, 0x22, 0x33, 0x44}), 23s + 424242us,
                     "< frame 123 23.424242 11223344 >"},
        ReceivedCase{Frame::data_frame(0x5, {}), 1s, "< frame 005 1.000000  >"},
        ReceivedCase{Frame::data_frame(0x7FF, {0, 1, 2, 3, 4, 5, 6, 0xFF}), 1'700'000'000s + 7us,
                     "< frame 7FF 1700000000.000007 00010203040506FF >"},
        ReceivedCase{extended_frame(0x123, {0xAB}), 0s, "< frame 00000123 0.000000 AB >"},
        ReceivedCase{extended_frame(0x1FFFFFFF, {}), 2s, "< frame 1FFFFFFF 2.000000  >"},
        ReceivedCase{Frame::remote_frame(0x123, 4), 23s + 424242us, "< rtr 123 23.424242 4 >"},
        ReceivedCase{Frame{.id = 0x40, .error = true, .dlc = 8}, 3s + 500ms,
                     "< error 040 3.500000 >"}));

TEST(SocketcandFormat, SendRoundTripsThroughTheParser) {
    for (const Frame& frame :
         {Frame::data_frame(0x000, {}), Frame::data_frame(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8}),
          extended_frame(0x5, {0x42}), extended_frame(0x1FFFFFFF, {0xFF, 0}),
          Frame::remote_frame(0x701, 1), Frame::remote_frame(0x100, 8, true)}) {
        const std::string text = format_send(frame);
        const Command command = parse_command(text);
        ASSERT_TRUE(std::holds_alternative<SendFrame>(command)) << text;
        EXPECT_EQ(std::get<SendFrame>(command).frame, frame) << text;
    }
    EXPECT_EQ(format_send(Frame::data_frame(0x123, {})), "< send 123 0 >");
    EXPECT_EQ(format_send(extended_frame(0x1AAAAAAA, {0x01, 0xF1})), "< send 1AAAAAAA 2 01 F1 >");
}

TEST(SocketcandFormat, ErrorReasonStaysOneMessage) {
    EXPECT_EQ(format_error("could not open bus"), "< error could not open bus >");
    EXPECT_EQ(format_error("a<b>c\n"), "< error a?b?c? >");
}

} // namespace
} // namespace eposp::can::io::socketcand
