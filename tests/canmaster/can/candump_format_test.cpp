#include "eposp/can/candump_format.hpp"
#include "trace_test_support.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <ostream>
#include <string>
#include <string_view>

namespace eposp::can {
namespace {

using namespace std::chrono_literals;

Frame error_frame(std::uint32_t error_class, std::initializer_list<std::uint8_t> details) {
    Frame frame = Frame::data_frame(error_class, details);
    frame.error = true;
    return frame;
}

struct FrameText {
    std::string_view name;
    Frame frame;
    std::string_view text;
    friend void PrintTo(const FrameText& c, std::ostream* os) { *os << c.name; }
};

class CandumpFrameText : public testing::TestWithParam<FrameText> {};

const FrameText kFrameTexts[] = {
    {"StandardData", Frame::data_frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF}), "123#DEADBEEF"},
    {"StandardEightBytes", Frame::data_frame(0x181, {1, 2, 3, 4, 5, 6, 7, 8}),
     "181#0102030405060708"},
    {"SmallIdKeepsThreeDigits", Frame::data_frame(0x000, {0x01, 0x00}), "000#0100"},
    {"EmptyData", Frame::data_frame(0x080, {}), "080#"},
    {"Extended", Frame::data_frame(0x1ABCDEF0, {0x11}, true), "1ABCDEF0#11"},
    {"ExtendedSmallIdHasEightDigits", Frame::data_frame(0x123, {}, true), "00000123#"},
    {"RemoteWithoutDlc", Frame::remote_frame(0x701, 0), "701#R"},
    {"RemoteWithDlc", Frame::remote_frame(0x123, 4), "123#R4"},
    {"RemoteExtended", Frame::remote_frame(0x12345678, 8, true), "12345678#R8"},
    // CAN_ERR_PROT with a bit-stuffing error in a data frame: a typical corrupted frame.
    {"ErrorFrame", error_frame(0x08, {0, 0, 0x04, 0, 0, 0, 0, 0}), "20000008#0000040000000000"},
    {"ErrorFrameBusOff", error_frame(0x40, {0, 0, 0, 0, 0, 0, 0, 0}), "20000040#0000000000000000"},
};

TEST_P(CandumpFrameText, FormatsAsCandumpWritesIt) {
    EXPECT_EQ(format_candump_frame(GetParam().frame), GetParam().text);
}

TEST_P(CandumpFrameText, ParsesBackToTheSameFrame) {
    const auto frame = parse_candump_frame(GetParam().text);
    ASSERT_TRUE(frame) << frame.error();
    EXPECT_EQ(*frame, GetParam().frame);
}

INSTANTIATE_TEST_SUITE_P(Candump, CandumpFrameText, testing::ValuesIn(kFrameTexts),
                         testing_support::row_name<FrameText>);

TEST(CandumpFormat, ParserAcceptsLowercaseHexAndDotSeparators) {
    const auto frame = parse_candump_frame("1ab#de.ad.be.ef");
    ASSERT_TRUE(frame) << frame.error();
    EXPECT_EQ(*frame, Frame::data_frame(0x1AB, {0xDE, 0xAD, 0xBE, 0xEF}));
}

TEST(CandumpFormat, ErrorFrameIdentifierLosesTheErrorFlag) {
    const auto frame = parse_candump_frame("20000004#0004000000000000");
    ASSERT_TRUE(frame) << frame.error();
    EXPECT_TRUE(frame->error);
    EXPECT_FALSE(frame->extended);
    EXPECT_EQ(frame->id, 0x04U);
    EXPECT_EQ(frame->dlc, 8);
    EXPECT_EQ(frame->data[1], 0x04);
}

TEST(CandumpFormat, LineHasPaddedSecondsAndMicroseconds) {
    const CandumpRecord record{TraceTime(1436509052s + 249713us), "can0",
                               Frame::data_frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF})};
    EXPECT_EQ(format_candump_line(record), "(1436509052.249713) can0 123#DEADBEEF");
}

TEST(CandumpFormat, LineOfVirtualRunStartsAtZero) {
    const CandumpRecord record{TraceTime(1500us), "can1", Frame::data_frame(0x080, {})};
    EXPECT_EQ(format_candump_line(record), "(0000000000.001500) can1 080#");
}

TEST(CandumpFormat, LineTruncatesNanosecondsToMicroseconds) {
    const CandumpRecord record{TraceTime(2s + 999'999'999ns), "can0",
                               Frame::remote_frame(0x701, 1)};
    EXPECT_EQ(format_candump_line(record), "(0000000002.999999) can0 701#R1");
}

TEST(CandumpFormat, LineRoundTrips) {
    const CandumpRecord record{TraceTime(1436509052s + 249713us), "vcan10",
                               Frame::data_frame(0x1FFFFFFF, {0xAA}, true)};
    const auto parsed = parse_candump_line(format_candump_line(record));
    ASSERT_TRUE(parsed) << parsed.error();
    EXPECT_EQ(*parsed, record);
}

struct GoodLine {
    std::string_view name;
    std::string_view line;
    friend void PrintTo(const GoodLine& c, std::ostream* os) { *os << c.name; }
};

class CandumpLineVariant : public testing::TestWithParam<GoodLine> {};

const GoodLine kGoodLines[] = {
    {"Plain", "(1436509052.249713) can0 123#DEADBEEF"},
    {"WithLineFeed", "(1436509052.249713) can0 123#DEADBEEF\n"},
    {"WithCarriageReturn", "(1436509052.249713) can0 123#DEADBEEF\r\n"},
    // candump pads names to the longest interface it listens on.
    {"PaddedInterface", "(1436509052.249713)   can0 123#DEADBEEF"},
    {"TabSeparated", "(1436509052.249713)\tcan0\t123#DEADBEEF"},
    {"ReceiveDirection", "(1436509052.249713) can0 123#DEADBEEF R"},
    {"TransmitDirection", "(1436509052.249713) can0 123#DEADBEEF T"},
};

TEST_P(CandumpLineVariant, ParsesToTheSameRecord) {
    const auto record = parse_candump_line(GetParam().line);
    ASSERT_TRUE(record) << record.error();
    EXPECT_EQ(record->time, TraceTime(1436509052s + 249713us));
    EXPECT_EQ(record->interface_name, "can0");
    EXPECT_EQ(record->frame, Frame::data_frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF}));
}

INSTANTIATE_TEST_SUITE_P(Candump, CandumpLineVariant, testing::ValuesIn(kGoodLines),
                         testing_support::row_name<GoodLine>);

struct BadLine {
    std::string_view name;
    std::string_view line;
    std::string_view reason; ///< a part of the error message
    friend void PrintTo(const BadLine& c, std::ostream* os) { *os << c.name; }
};

class CandumpMalformedLine : public testing::TestWithParam<BadLine> {};

const BadLine kBadLines[] = {
    {"Empty", "", "must start with '('"},
    {"NoTimestamp", "can0 123#00", "must start with '('"},
    {"UnclosedTimestamp", "(1436509052.249713 can0 123#00", "missing ')'"},
    {"TimestampWithoutDot", "(1436509052) can0 123#00", "seconds.microseconds"},
    {"TimestampWithoutSeconds", "(.249713) can0 123#00", "seconds must be decimal"},
    {"NegativeTimestamp", "(-1.249713) can0 123#00", "seconds must be decimal"},
    {"TimestampOutOfRange", "(99999999999999999999.000000) can0 123#00", "out of range"},
    {"TimestampMillis", "(1436509052.249) can0 123#00", "6 digits"},
    {"TimestampNanos", "(1436509052.249713000) can0 123#00", "6 digits"},
    {"TimestampLetter", "(1436509052.24971x) can0 123#00", "invalid decimal digit 'x'"},
    {"NoInterface", "(1436509052.249713)", "missing interface"},
    {"NoFrame", "(1436509052.249713) can0", "missing frame"},
    {"TrailingText", "(1436509052.249713) can0 123#00 hello", "unexpected text"},
    {"TooManyFields", "(1436509052.249713) can0 123#00 R R", "unexpected text"},
    {"NoHash", "(1436509052.249713) can0 12300", "missing '#'"},
    {"ShortId", "(1436509052.249713) can0 12#00", "3 (standard) or 8 (extended)"},
    {"FourDigitId", "(1436509052.249713) can0 1234#00", "3 (standard) or 8 (extended)"},
    {"StandardIdTooLarge", "(1436509052.249713) can0 800#00", "above 0x7FF"},
    {"ExtendedIdTooLarge", "(1436509052.249713) can0 80000000#00", "above 0x1FFFFFFF"},
    {"ErrorWithEffFlag", "(1436509052.249713) can0 A0000000#00", "EFF/RTR"},
    {"BadIdDigit", "(1436509052.249713) can0 12G#00", "invalid hex digit 'G' in identifier"},
    {"SignedId", "(1436509052.249713) can0 -12#00", "invalid hex digit '-'"},
    {"BadDataDigit", "(1436509052.249713) can0 123#00Z1", "invalid hex digit 'Z' in data byte 2"},
    {"ControlByte", std::string_view("(1.000000) can0 123#0\x01", 22), "byte 0x01"},
    {"OddDigits", "(1436509052.249713) can0 123#001", "data byte 2 has only one hex digit"},
    {"NineBytes", "(1436509052.249713) can0 123#000102030405060708", "more than 8 data bytes"},
    {"CanFd", "(1436509052.249713) can0 123##100", "CAN FD"},
    {"RemoteDlcTooLarge", "(1436509052.249713) can0 123#R9", "DLC digit 0..8"},
    {"RemoteWithData", "(1436509052.249713) can0 123#R12", "DLC digit 0..8"},
    {"RemoteErrorFrame", "(1436509052.249713) can0 20000004#R", "cannot be a remote frame"},
};

TEST_P(CandumpMalformedLine, IsRejectedWithReason) {
    const auto record = parse_candump_line(GetParam().line);
    ASSERT_FALSE(record);
    EXPECT_NE(record.error().find(GetParam().reason), std::string::npos) << record.error();
}

INSTANTIATE_TEST_SUITE_P(Candump, CandumpMalformedLine, testing::ValuesIn(kBadLines),
                         testing_support::row_name<BadLine>);

} // namespace
} // namespace eposp::can
