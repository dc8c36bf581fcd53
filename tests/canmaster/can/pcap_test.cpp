#include "eposp/can/pcap_reader.hpp"
#include "eposp/can/pcap_writer.hpp"
#include "trace_test_support.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace eposp::can {
namespace {

using namespace std::chrono_literals;
using testing_support::row_name;
using testing_support::TempFile;

Frame error_frame(std::uint32_t error_class) {
    Frame frame = Frame::data_frame(error_class, {0, 0, 0x04, 0, 0, 0, 0, 0});
    frame.error = true;
    return frame;
}

std::string bytes(std::initializer_list<unsigned> values) {
    std::string text;
    for (const unsigned value : values) {
        text += static_cast<char>(value);
    }
    return text;
}

const std::string kNanosecondHeader = bytes(
    {0x4D, 0x3C, 0xB2, 0xA1, 2, 0, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xFF, 0xFF, 0, 0, 227, 0, 0, 0});

TEST(PcapWriter, FileHeaderIsNanosecondPcapOfSocketCanFrames) {
    std::ostringstream out;
    const PcapWriter writer{TraceOutput(out)};
    EXPECT_EQ(out.str(), kNanosecondHeader);
}

TEST(PcapWriter, RecordHasNanosecondTimeAndBigEndianCanId) {
    std::ostringstream out;
    PcapWriter writer{TraceOutput(out)};
    writer.record(TraceTime(3s + 1234ns), "can0",
                  Frame::data_frame(0x12345678, {0xAA, 0xBB}, true));
    EXPECT_EQ(out.str().substr(kNanosecondHeader.size()),
              bytes({3,    0,    0,    0,    0xD2, 0x04, 0, 0,
                     16,   0,    0,    0,    16,   0,    0, 0, // record header
                     0x92, 0x34, 0x56, 0x78, 2,    0,    0, 0,
                     0xAA, 0xBB, 0,    0,    0,    0,    0, 0})); // frame
}

TEST(PcapWriter, FileIsReadableWhileTheWriterIsOpen) {
    const TempFile file(".pcap");
    auto output = TraceOutput::create(file.path());
    ASSERT_TRUE(output) << output.error();
    PcapWriter writer(std::move(*output));
    writer.record(TraceTime(1ms), "can0", Frame::data_frame(0x080, {}));
    const auto capture = read_pcap_file(file.path());
    ASSERT_TRUE(capture) << capture.error();
    EXPECT_EQ(capture->records.size(), 1U);
}

TEST(Pcap, FramesRoundTripThroughAFile) {
    const std::vector<PcapRecord> written = {
        {TraceTime(1436509052s + 1ns), 16, Frame::data_frame(0x000, {0x01, 0x00})},
        {TraceTime(1436509052s + 2us), 16, Frame::data_frame(0x080, {})},
        {TraceTime(1436509052s + 3ms), 16, Frame::data_frame(0x1FFFFFFF, {1, 2, 3}, true)},
        {TraceTime(1436509053s), 16, Frame::remote_frame(0x701, 1)},
        {TraceTime(1436509054s), 16, Frame::remote_frame(0x1234, 8, true)},
        {TraceTime(1436509055s), 16, Frame::data_frame(0x7FF, {1, 2, 3, 4, 5, 6, 7, 8})},
        {TraceTime(1436509056s), 16, error_frame(0x08)},
    };
    const TempFile file(".pcap");
    {
        auto output = TraceOutput::create(file.path());
        ASSERT_TRUE(output) << output.error();
        PcapWriter writer(std::move(*output));
        for (const auto& record : written) {
            writer.record(record.time, "can0", record.frame);
        }
        EXPECT_TRUE(writer.good());
    }
    const auto capture = read_pcap_file(file.path());
    ASSERT_TRUE(capture) << capture.error();
    EXPECT_EQ(capture->header.magic, 0xA1B23C4DU);
    EXPECT_EQ(capture->header.byte_order, std::endian::little);
    EXPECT_EQ(capture->header.version_major, 2);
    EXPECT_EQ(capture->header.version_minor, 4);
    EXPECT_EQ(capture->header.snap_length, 65535U);
    EXPECT_EQ(capture->header.link_type, 227U);
    ASSERT_EQ(capture->records.size(), written.size());
    for (std::size_t i = 0; i < written.size(); ++i) {
        EXPECT_EQ(capture->records[i].time, written[i].time) << "record " << i;
        EXPECT_EQ(capture->records[i].length, 16U) << "record " << i;
        EXPECT_EQ(capture->records[i].frame, written[i].frame) << "record " << i;
    }
}

TEST(PcapReader, ReadsBigEndianMicrosecondFiles) {
    // As a big-endian host's libpcap writes it; the frame has only its 2 payload bytes.
    std::istringstream in(
        bytes({0xA1, 0xB2, 0xC3, 0xD4, 0, 2, 0,    4,    0,    0,   0, 0,  0, 0, 0, 0,
               0,    0,    0,    16,   0, 0, 0,    227, // file header
               0,    0,    0,    7,    0, 0, 0x01, 0xF4, 0,    0,   0, 10, 0, 0, 0, 10, // record
               0x00, 0x00, 0x01, 0x81, 2, 0, 0,    0,    0x11, 0x22}));
    const auto capture = read_pcap(in);
    ASSERT_TRUE(capture) << capture.error();
    EXPECT_EQ(capture->header.byte_order, std::endian::big);
    ASSERT_EQ(capture->records.size(), 1U);
    EXPECT_EQ(capture->records[0].time, TraceTime(7s + 500us));
    EXPECT_EQ(capture->records[0].frame, Frame::data_frame(0x181, {0x11, 0x22}));
}

struct BadPcap {
    std::string_view name;
    std::string file;
    std::string_view reason;
    friend void PrintTo(const BadPcap& c, std::ostream* os) { *os << c.name; }
};

std::string header_with(std::size_t offset, std::initializer_list<unsigned> values) {
    std::string header = kNanosecondHeader;
    for (const unsigned value : values) {
        header[offset++] = static_cast<char>(value);
    }
    return header;
}

std::string record(std::initializer_list<unsigned> record_header, std::string frame) {
    return bytes(record_header) + frame;
}

const std::string kFrame = bytes({0, 0, 0x01, 0x81, 1, 0, 0, 0, 0x55, 0, 0, 0, 0, 0, 0, 0});
const std::initializer_list<unsigned> kGoodRecordHeader = {0,  0, 0, 0, 0,  0, 0, 0,
                                                           16, 0, 0, 0, 16, 0, 0, 0};

class MalformedPcap : public testing::TestWithParam<BadPcap> {};

const BadPcap kBadFiles[] = {
    {"Empty", "", "too short for a pcap file header"},
    {"ShortHeader", kNanosecondHeader.substr(0, 20), "too short"},
    {"UnknownMagic", header_with(0, {1, 2, 3, 4}), "not a pcap file (magic 0x04030201)"},
    {"Pcapng", header_with(0, {0x0A, 0x0D, 0x0D, 0x0A}), "pcapng"},
    {"WrongVersion", header_with(4, {2, 0, 3, 0}), "version 2.3 is not 2.4"},
    {"ZeroSnapLength", header_with(16, {0, 0, 0, 0}), "snap length is 0"},
    {"EthernetLinkType", header_with(20, {1, 0, 0, 0}), "link type 1 is not LINKTYPE_CAN"},
    {"ShortRecordHeader", kNanosecondHeader + bytes({0, 0, 0}), "record 1: record header"},
    {"CutData", kNanosecondHeader + record(kGoodRecordHeader, kFrame.substr(0, 10)),
     "record 1: packet data of 16 bytes is cut short"},
    {"TruncatedCapture",
     kNanosecondHeader + record({0, 0, 0, 0, 0, 0, 0, 0, 8, 0, 0, 0, 16, 0, 0, 0}, kFrame),
     "truncated: 8 of 16"},
    {"AboveSnapLength", header_with(16, {8, 0, 0, 0}) + record(kGoodRecordHeader, kFrame),
     "above the snap length 8"},
    {"NanosecondsOutOfRange",
     kNanosecondHeader +
         record({0, 0, 0, 0, 0x00, 0xCA, 0x9A, 0x3B, 16, 0, 0, 0, 16, 0, 0, 0}, kFrame),
     "sub-second timestamp 1000000000"},
    {"NoCanHeader",
     kNanosecondHeader +
         record({0, 0, 0, 0, 0, 0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0}, "\x01\x02\x03\x04"),
     "too short for a SocketCAN frame header"},
    {"CanFdLength",
     kNanosecondHeader + record(kGoodRecordHeader, bytes({0, 0, 1, 0x81, 12}) + kFrame.substr(5)),
     "payload length 12 is above 8"},
    {"PayloadCutShort",
     kNanosecondHeader + record({0, 0, 0, 0, 0, 0, 0, 0, 9, 0, 0, 0, 9, 0, 0, 0},
                                bytes({0, 0, 0x01, 0x81, 2, 0, 0, 0, 0x55})),
     "record 1: payload of 2 bytes is cut short"},
    {"StandardIdTooLarge",
     kNanosecondHeader + record(kGoodRecordHeader, bytes({0, 0, 0x08, 0x00}) + kFrame.substr(4)),
     "standard identifier 0x800"},
    {"SecondRecordBad", kNanosecondHeader + record(kGoodRecordHeader, kFrame) + bytes({0}),
     "record 2:"},
};

TEST_P(MalformedPcap, IsRejectedWithReason) {
    std::istringstream in(GetParam().file);
    const auto capture = read_pcap(in);
    ASSERT_FALSE(capture);
    EXPECT_NE(capture.error().find(GetParam().reason), std::string::npos) << capture.error();
}

INSTANTIATE_TEST_SUITE_P(Pcap, MalformedPcap, testing::ValuesIn(kBadFiles), row_name<BadPcap>);

TEST(PcapReader, FileErrorsNameTheFile) {
    const TempFile file(".pcap");
    {
        std::ofstream out(file.path(), std::ios::binary);
        out << "this is not a capture file";
    }
    const auto capture = read_pcap_file(file.path());
    ASSERT_FALSE(capture);
    EXPECT_EQ(capture.error(), file.path().string() + ": not a pcap file (magic 0x73696874)");
}

} // namespace
} // namespace eposp::can
