#include "sdo_test_support.hpp"

#include <gtest/gtest.h>

// Block transfers (CiA 301 7.2.4.3.8 ff. block download, 7.2.4.3.12 ff. block upload): the
// server driven by raw frames, and the client against a raw-frame server.

namespace eposp::canopen {
namespace {

using namespace testing;

/// Segments `first`.. of a sub-block carrying `data` from byte `offset` (seqno from 1, c on the
/// segment with the last byte), up to `count` of them, on `cob_id`.
Replies sub_block(std::uint32_t cob_id, const Bytes& data, std::size_t offset, std::size_t count) {
    Replies out;
    for (std::size_t k = 1; k <= count && (k == 1 || offset < data.size()); ++k) {
        const std::size_t size = std::min<std::size_t>(7, data.size() - offset);
        Bytes segment(data.begin() + static_cast<std::ptrdiff_t>(offset),
                      data.begin() + static_cast<std::ptrdiff_t>(offset + size));
        segment.resize(7);
        offset += size;
        const bool last = offset == data.size();
        out.push_back(fmt::format("{:03X}#{:02X}{}", cob_id, (last ? 0x80 : 0) | k, hex(segment)));
        if (last) {
            break;
        }
    }
    return out;
}

/// The end message of a block transfer of `data` with command specifier `cs` (6 both ways).
std::string block_end(std::uint32_t cob_id, const Bytes& data) {
    const std::size_t used = data.size() % 7;
    const std::size_t unused = data.empty() ? 7 : (used == 0 ? 0 : 7 - used);
    return fmt::format("{:03X}#{:02X}{}0000000000", cob_id, 0xC1 | unused << 2, crc_hex(data));
}

/// The tester sends `frames` back to back, waiting whenever its transmit queue is full.
void send_all(SdoBench& bench, const Replies& frames) {
    for (const std::string& frame : frames) {
        while (bench.tester->send(*can::parse_candump_frame(frame)) ==
               can::SendStatus::TxOverflow) {
            bench.run_for(1ms);
        }
    }
}

// The server: block download.

TEST(SdoBlockDownload, TwentyBytesInOneSubBlockWithCrc) {
    SdoServerBench bench;
    const Bytes data = counting_bytes(20);
    EXPECT_EQ(bench.exchange("605#C600210014000000"), Replies{"585#A40021007F000000"});
    EXPECT_EQ(bench.exchange("605#0101020304050607"), Replies{});
    EXPECT_EQ(bench.exchange("605#0208090A0B0C0D0E"), Replies{});
    EXPECT_EQ(bench.exchange("605#830F101112131400"), Replies{"585#A2037F0000000000"});
    EXPECT_TRUE(bench.od.get(0x2100, 0).empty()) << "stored only after the end message";
    EXPECT_EQ(bench.exchange(block_end(0x605, data)), Replies{"585#A100000000000000"});
    EXPECT_EQ(bench.od.get(0x2100, 0), data);
    EXPECT_FALSE(bench.server.busy());
}

TEST(SdoBlockDownload, ServerBlockSizeIsConfigurable) {
    SdoServerBench bench(SdoServerConfig{.block_size = 2});
    const Bytes data = counting_bytes(20);
    EXPECT_EQ(bench.exchange("605#C600210014000000"), Replies{"585#A400210002000000"});
    send_all(bench, sub_block(0x605, data, 0, 2));
    EXPECT_EQ(bench.settle(), Replies{"585#A202020000000000"});
    send_all(bench, sub_block(0x605, data, 14, 2));
    EXPECT_EQ(bench.settle(), Replies{"585#A201020000000000"});
    EXPECT_EQ(bench.exchange(block_end(0x605, data)), Replies{"585#A100000000000000"});
    EXPECT_EQ(bench.od.get(0x2100, 0), data);
}

TEST(SdoBlockDownload, LostSegmentIsRepeatedAfterTheLastAcknowledgedOne) {
    SdoServerBench bench;
    const Bytes data = counting_bytes(20);
    bench.exchange("605#C600210014000000");
    EXPECT_EQ(bench.exchange("605#0101020304050607"), Replies{});
    // Segment 2 is lost; the last one still ends the sub-block.
    EXPECT_EQ(bench.exchange("605#830F101112131400"), Replies{"585#A2017F0000000000"});
    send_all(bench, sub_block(0x605, data, 7, 127));
    EXPECT_EQ(bench.settle(), Replies{"585#A2027F0000000000"});
    EXPECT_EQ(bench.exchange(block_end(0x605, data)), Replies{"585#A100000000000000"});
    EXPECT_EQ(bench.od.get(0x2100, 0), data);
}

TEST(SdoBlockDownload, SeveralSubBlocksOfFullSize) {
    SdoServerBench bench;
    const Bytes data = counting_bytes(2000); // 286 segments: 127 + 127 + 32
    bench.exchange("605#C6002100D0070000");
    for (std::size_t offset = 0, acks = 0; offset < data.size(); offset += 127 * 7, ++acks) {
        const Replies segments = sub_block(0x605, data, offset, 127);
        send_all(bench, segments);
        bench.run_for(100ms);
        const Replies ack = bench.new_device_frames();
        ASSERT_EQ(ack, Replies{fmt::format("585#A2{:02X}7F0000000000", segments.size())})
            << "block " << acks;
    }
    EXPECT_EQ(bench.exchange(block_end(0x605, data)), Replies{"585#A100000000000000"});
    EXPECT_EQ(bench.od.get(0x2100, 0), data);
}

TEST(SdoBlockDownload, EmptyValueIsOneSegmentWithoutData) {
    SdoServerBench bench;
    bench.od.set(0x2100, 0, counting_bytes(3));
    EXPECT_EQ(bench.exchange("605#C600210000000000"), Replies{"585#A40021007F000000"});
    EXPECT_EQ(bench.exchange("605#8100000000000000"), Replies{"585#A2017F0000000000"});
    EXPECT_EQ(bench.exchange("605#DD00000000000000"), Replies{"585#A100000000000000"});
    EXPECT_TRUE(bench.od.get(0x2100, 0).empty());
}

TEST(SdoBlockDownload, SmallValueByBlock) {
    SdoServerBench bench;
    bench.exchange("605#C602200004000000");
    EXPECT_EQ(bench.exchange("605#8178563412000000"), Replies{"585#A2017F0000000000"});
    const Bytes value = {0x78, 0x56, 0x34, 0x12};
    EXPECT_EQ(bench.exchange(block_end(0x605, value)), Replies{"585#A100000000000000"});
    EXPECT_EQ(bench.od.get_as<std::uint32_t>(0x2002, 0), 0x12345678U);
}

TEST(SdoBlockDownload, WithoutClientCrcTheCrcFieldIsIgnored) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#C200210003000000"), Replies{"585#A40021007F000000"});
    bench.exchange("605#8101020300000000");
    EXPECT_EQ(bench.exchange("605#D1FFFF0000000000"), Replies{"585#A100000000000000"});
    EXPECT_EQ(bench.od.get(0x2100, 0), counting_bytes(3));
}

TEST(SdoBlockDownload, WrongCrcAborts) {
    SdoServerBench bench;
    bench.exchange("605#C600210003000000");
    bench.exchange("605#8101020300000000");
    EXPECT_EQ(bench.exchange("605#D100000000000000"), Replies{"585#8000210004000405"});
    EXPECT_TRUE(bench.od.get(0x2100, 0).empty());
}

TEST(SdoBlockDownload, SequenceNumberZeroAborts) {
    SdoServerBench bench;
    bench.exchange("605#C600210014000000");
    EXPECT_EQ(bench.exchange("605#0001020304050607"), Replies{"585#8000210003000405"});
}

TEST(SdoBlockDownload, SequenceNumberAboveTheBlockSizeAborts) {
    SdoServerBench bench(SdoServerConfig{.block_size = 2});
    bench.exchange("605#C600210014000000");
    bench.exchange("605#0101020304050607");
    EXPECT_EQ(bench.exchange("605#0308090A0B0C0D0E"), Replies{"585#8000210003000405"});
}

TEST(SdoBlockDownload, LessDataThanIndicatedAbortsAtTheEnd) {
    SdoServerBench bench;
    const Bytes data = counting_bytes(20);
    bench.exchange("605#C600210015000000");
    send_all(bench, sub_block(0x605, data, 0, 127));
    bench.settle();
    EXPECT_EQ(bench.exchange(block_end(0x605, data)), Replies{"585#8000210013000706"});
}

TEST(SdoBlockDownload, MoreDataThanIndicatedAbortsAtTheEnd) {
    SdoServerBench bench;
    const Bytes data = counting_bytes(20);
    bench.exchange("605#C600210013000000");
    send_all(bench, sub_block(0x605, data, 0, 127));
    bench.settle();
    EXPECT_EQ(bench.exchange(block_end(0x605, data)), Replies{"585#8000210012000706"});
}

TEST(SdoBlockDownload, MuchMoreDataThanIndicatedAbortsInTheSubBlock) {
    SdoServerBench bench;
    bench.exchange("605#C600210008000000");
    send_all(bench, sub_block(0x605, counting_bytes(30), 0, 3));
    EXPECT_EQ(bench.settle(), Replies{"585#8000210012000706"});
}

TEST(SdoBlockDownload, RefusedAtTheInitiateRequest) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#C600100004000000"), Replies{"585#8000100002000106"});
    EXPECT_EQ(bench.exchange("605#C602200008000000"), Replies{"585#8002200012000706"});
}

TEST(SdoBlockDownload, OtherCommandInsteadOfTheEndAborts) {
    SdoServerBench bench;
    bench.exchange("605#C600210003000000");
    bench.exchange("605#8101020300000000");
    EXPECT_EQ(bench.exchange("605#A100000000000000"), Replies{"585#8000210001000405"});
}

TEST(SdoBlockDownload, AbortInASubBlockEndsSilently) {
    SdoServerBench bench;
    bench.exchange("605#C600210014000000");
    EXPECT_EQ(bench.exchange("605#8000210000000008"), Replies{});
    EXPECT_FALSE(bench.server.busy());
}

TEST(SdoBlockDownload, MissingSegmentsTimeOut) {
    SdoServerBench bench;
    bench.exchange("605#C600210014000000");
    bench.exchange("605#0101020304050607");
    bench.run_for(990ms);
    EXPECT_EQ(bench.new_device_frames(), Replies{});
    EXPECT_EQ(bench.settle(), Replies{"585#8000210000000405"});
}

// The server: block upload.

TEST(SdoBlockUpload, TwelveBytesWithCrc) {
    SdoServerBench bench;
    const Bytes name(kDeviceName.begin(), kDeviceName.end());
    EXPECT_EQ(bench.exchange("605#A40810007F000000"), Replies{"585#C60810000C000000"});
    EXPECT_EQ(bench.exchange("605#A300000000000000"),
              (Replies{"585#0145504F53322032", "585#82342F3520580000"}));
    EXPECT_EQ(bench.exchange("605#A2027F0000000000"), Replies{block_end(0x585, name)});
    EXPECT_EQ(bench.exchange("605#A100000000000000"), Replies{});
    EXPECT_FALSE(bench.server.busy());
}

TEST(SdoBlockUpload, ClientBlockSizeLimitsEachSubBlock) {
    SdoServerBench bench;
    bench.exchange("605#A408100001000000");
    EXPECT_EQ(bench.exchange("605#A300000000000000"), Replies{"585#0145504F53322032"});
    EXPECT_EQ(bench.exchange("605#A201010000000000"), Replies{"585#81342F3520580000"});
    EXPECT_EQ(bench.exchange("605#A201010000000000").size(), 1U) << "the end message";
}

TEST(SdoBlockUpload, LostSegmentIsRepeatedInTheNextSubBlock) {
    SdoServerBench bench;
    bench.exchange("605#A40810007F000000");
    bench.exchange("605#A300000000000000");
    EXPECT_EQ(bench.exchange("605#A2017F0000000000"), Replies{"585#81342F3520580000"});
    const Bytes name(kDeviceName.begin(), kDeviceName.end());
    EXPECT_EQ(bench.exchange("605#A2017F0000000000"), Replies{block_end(0x585, name)});
}

TEST(SdoBlockUpload, ProtocolSwitchThresholdSelectsThePlainUpload) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#A40010007F040000"), Replies{"585#4300100092010200"});
    EXPECT_FALSE(bench.server.busy());
    EXPECT_EQ(bench.exchange("605#A40810007F0C0000"), Replies{"585#410810000C000000"});
    EXPECT_EQ(bench.exchange("605#6000000000000000"), Replies{"585#0045504F53322032"});
    EXPECT_EQ(bench.exchange("605#7000000000000000"), Replies{"585#15342F3520580000"});
    EXPECT_EQ(bench.exchange("605#A40810007F0B0000"), Replies{"585#C60810000C000000"})
        << "above the threshold: block";
}

TEST(SdoBlockUpload, WithoutClientCrcTheEndCarriesNone) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#A00810007F000000"), Replies{"585#C60810000C000000"});
    bench.exchange("605#A300000000000000");
    EXPECT_EQ(bench.exchange("605#A2027F0000000000"), Replies{"585#C900000000000000"});
}

TEST(SdoBlockUpload, EmptyValueIsOneSegmentWithoutData) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#A40021007F000000"), Replies{"585#C600210000000000"});
    EXPECT_EQ(bench.exchange("605#A300000000000000"), Replies{"585#8100000000000000"});
    EXPECT_EQ(bench.exchange("605#A2017F0000000000"), Replies{"585#DD00000000000000"});
}

TEST(SdoBlockUpload, MoreSegmentsThanTheTransmitQueueHolds) {
    SdoServerBench bench;
    const Bytes data = counting_bytes(127 * 7);
    bench.od.set(0x2100, 0, data);
    bench.exchange("605#A40021007F000000");
    bench.send("605#A300000000000000");
    bench.run_for(100ms);
    EXPECT_EQ(bench.new_device_frames(), sub_block(0x585, data, 0, 127));
    EXPECT_EQ(bench.exchange("605#A27F7F0000000000"), Replies{block_end(0x585, data)});
}

struct BlockUploadAbort {
    const char* name;
    std::vector<const char*> requests; ///< the last one is answered with `reply`
    const char* reply;
};

void PrintTo(const BlockUploadAbort& c, std::ostream* os) {
    *os << c.name;
}

class SdoBlockUploadAbort : public ::testing::TestWithParam<BlockUploadAbort> {};

TEST_P(SdoBlockUploadAbort, AbortsWithTheCode) {
    SdoServerBench bench;
    Replies replies;
    for (const char* request : GetParam().requests) {
        replies = bench.exchange(request);
    }
    EXPECT_EQ(replies, Replies{GetParam().reply});
    EXPECT_FALSE(bench.server.busy());
}

INSTANTIATE_TEST_SUITE_P(
    Table, SdoBlockUploadAbort,
    ::testing::Values(
        BlockUploadAbort{"BlockSizeZero", {"605#A408100000000000"}, "585#8008100002000405"},
        BlockUploadAbort{"BlockSize128", {"605#A408100080000000"}, "585#8008100002000405"},
        BlockUploadAbort{"MissingObject", {"605#A40030007F000000"}, "585#8000300000000206"},
        BlockUploadAbort{"WriteOnly", {"605#A40520007F000000"}, "585#8005200001000106"},
        BlockUploadAbort{"AckBeyondTheSentSegments",
                         {"605#A40810007F000000", "605#A300000000000000", "605#A2037F0000000000"},
                         "585#8008100003000405"},
        BlockUploadAbort{"AckWithBlockSizeZero",
                         {"605#A40810007F000000", "605#A300000000000000", "605#A201000000000000"},
                         "585#8008100002000405"},
        BlockUploadAbort{"OtherCommandInsteadOfStart",
                         {"605#A40810007F000000", "605#A200000000000000"},
                         "585#8008100001000405"},
        BlockUploadAbort{"OtherCommandInsteadOfTheEndResponse",
                         {"605#A40810007F000000", "605#A300000000000000", "605#A2027F0000000000",
                          "605#A300000000000000"},
                         "585#8008100001000405"}),
    [](const auto& row) { return std::string(row.param.name); });

TEST(SdoBlockUpload, MissingAcknowledgementTimesOut) {
    SdoServerBench bench;
    bench.exchange("605#A40810007F000000");
    bench.exchange("605#A300000000000000");
    bench.run_for(2s);
    EXPECT_EQ(bench.new_device_frames(), Replies{"585#8008100000000405"});
}

// The client against a raw-frame server.

TEST(SdoClientBlock, DownloadSendsSubBlocksAndEndsWithTheCrc) {
    SdoClientBench bench;
    Outcome outcome;
    const Bytes data = counting_bytes(20);
    bench.client.download(kServerNode, 0x2100, 0, data, outcome.download(),
                          {.protocol = SdoProtocol::Block});
    EXPECT_EQ(bench.settle(), Replies{"605#C600210014000000"});
    EXPECT_EQ(bench.exchange("585#A40021007F000000"), sub_block(0x605, data, 0, 127));
    EXPECT_EQ(bench.exchange("585#A2037F0000000000"), Replies{block_end(0x605, data)});
    EXPECT_FALSE(outcome.code);
    EXPECT_EQ(bench.exchange("585#A100000000000000"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::None);
}

TEST(SdoClientBlock, DownloadRepeatsWhatTheServerDidNotAcknowledge) {
    SdoClientBench bench;
    Outcome outcome;
    const Bytes data = counting_bytes(20);
    bench.client.download(kServerNode, 0x2100, 0, data, outcome.download(),
                          {.protocol = SdoProtocol::Block});
    bench.settle();
    bench.exchange("585#A40021007F000000");
    EXPECT_EQ(bench.exchange("585#A2017F0000000000"), sub_block(0x605, data, 7, 127));
    EXPECT_EQ(bench.exchange("585#A2027F0000000000"), Replies{block_end(0x605, data)});
    bench.exchange("585#A100000000000000");
    EXPECT_EQ(outcome.code, AbortCode::None);
}

TEST(SdoClientBlock, DownloadFollowsTheServersBlockSize) {
    SdoClientBench bench;
    Outcome outcome;
    const Bytes data = counting_bytes(20);
    bench.client.download(kServerNode, 0x2100, 0, data, outcome.download(),
                          {.protocol = SdoProtocol::Block});
    bench.settle();
    EXPECT_EQ(bench.exchange("585#A400210001000000"), sub_block(0x605, data, 0, 1));
    EXPECT_EQ(bench.exchange("585#A201020000000000"), sub_block(0x605, data, 7, 2));
}

TEST(SdoClientBlock, UploadAcknowledgesAndChecksTheCrc) {
    SdoClientBench bench;
    Outcome outcome;
    const Bytes name(kDeviceName.begin(), kDeviceName.end());
    bench.client.upload(kServerNode, 0x1008, 0, outcome.upload(),
                        {.protocol = SdoProtocol::Block, .protocol_switch_threshold = 0});
    EXPECT_EQ(bench.settle(), Replies{"605#A40810007F000000"});
    EXPECT_EQ(bench.exchange("585#C60810000C000000"), Replies{"605#A300000000000000"});
    send_all(bench, sub_block(0x585, name, 0, 127));
    EXPECT_EQ(bench.settle(), Replies{"605#A2027F0000000000"});
    EXPECT_EQ(bench.exchange(block_end(0x585, name)), Replies{"605#A100000000000000"});
    EXPECT_EQ(outcome.code, AbortCode::None);
    EXPECT_EQ(outcome.value, name);
}

TEST(SdoClientBlock, UploadAcknowledgesTheLastSegmentInSequence) {
    SdoClientBench bench;
    Outcome outcome;
    const Bytes data = counting_bytes(20);
    bench.client.upload(kServerNode, 0x2100, 0, outcome.upload(), {.protocol = SdoProtocol::Block});
    bench.settle();
    bench.exchange("585#C600210014000000");
    const Replies segments = sub_block(0x585, data, 0, 127);
    bench.send(segments[0]);
    bench.send(segments[2]); // segment 2 lost
    EXPECT_EQ(bench.settle(), Replies{"605#A2017F0000000000"});
    send_all(bench, sub_block(0x585, data, 7, 127));
    EXPECT_EQ(bench.settle(), Replies{"605#A2027F0000000000"});
    bench.exchange(block_end(0x585, data));
    EXPECT_EQ(outcome.value, data);
}

TEST(SdoClientBlock, UploadTakesTheProtocolSwitch) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1000, 0, outcome.upload(), {.protocol = SdoProtocol::Block});
    EXPECT_EQ(bench.settle(), Replies{"605#A40010007F040000"});
    EXPECT_EQ(bench.exchange("585#4300100092010200"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::None);
    EXPECT_EQ(outcome.value, encode<std::uint32_t>(0x0002'0192));
}

struct ClientBlockViolation {
    const char* name;
    bool upload;
    std::vector<const char*> server_frames; ///< the client aborts on the last one
    const char* client_abort;
    AbortCode code;
};

void PrintTo(const ClientBlockViolation& c, std::ostream* os) {
    *os << c.name;
}

class SdoClientBlockViolation : public ::testing::TestWithParam<ClientBlockViolation> {};

TEST_P(SdoClientBlockViolation, AbortsTheTransferWithTheCode) {
    const ClientBlockViolation& c = GetParam();
    SdoClientBench bench;
    Outcome outcome;
    const SdoRequestOptions block{.protocol = SdoProtocol::Block, .protocol_switch_threshold = 0};
    if (c.upload) {
        bench.client.upload(kServerNode, 0x2100, 0, outcome.upload(), block);
    } else {
        bench.client.download(kServerNode, 0x2100, 0, counting_bytes(20), outcome.download(),
                              block);
    }
    bench.settle();
    Replies last;
    for (const char* frame : c.server_frames) {
        last = bench.exchange(frame);
    }
    EXPECT_EQ(last, Replies{c.client_abort});
    EXPECT_EQ(outcome.code, c.code);
    EXPECT_EQ(outcome.calls, 1);
    EXPECT_FALSE(bench.client.busy(kServerNode));
}

INSTANTIATE_TEST_SUITE_P(
    Table, SdoClientBlockViolation,
    ::testing::Values(ClientBlockViolation{"DownloadBlockSizeZero",
                                           false,
                                           {"585#A400210000000000"},
                                           "605#8000210002000405",
                                           AbortCode::InvalidBlockSize},
                      ClientBlockViolation{"DownloadBlockSize128",
                                           false,
                                           {"585#A400210080000000"},
                                           "605#8000210002000405",
                                           AbortCode::InvalidBlockSize},
                      ClientBlockViolation{"DownloadAckBeyondTheSentSegments",
                                           false,
                                           {"585#A40021007F000000", "585#A2047F0000000000"},
                                           "605#8000210003000405",
                                           AbortCode::InvalidSequenceNumber},
                      ClientBlockViolation{"DownloadWrongIndexEcho",
                                           false,
                                           {"585#A40121007F000000"},
                                           "605#8000210000000008",
                                           AbortCode::GeneralError},
                      ClientBlockViolation{"DownloadPlainResponse",
                                           false,
                                           {"585#6000210000000000"},
                                           "605#8000210001000405",
                                           AbortCode::CommandSpecifier},
                      ClientBlockViolation{
                          "UploadWrongCrc",
                          true,
                          {"585#C600210003000000", "585#8101020300000000", "585#D100000000000000"},
                          "605#8000210004000405",
                          AbortCode::CrcError},
                      ClientBlockViolation{"UploadSequenceNumberZero",
                                           true,
                                           {"585#C600210003000000", "585#0001020300000000"},
                                           "605#8000210003000405",
                                           AbortCode::InvalidSequenceNumber},
                      ClientBlockViolation{"UploadSwitchNotOffered",
                                           true,
                                           {"585#4300210001020304"},
                                           "605#8000210001000405",
                                           AbortCode::CommandSpecifier},
                      ClientBlockViolation{
                          "UploadLessThanIndicated",
                          true,
                          {"585#C200210004000000", "585#8101020300000000", "585#D100000000000000"},
                          "605#8000210013000706",
                          AbortCode::LengthTooLow}),
    [](const auto& row) { return std::string(row.param.name); });

} // namespace
} // namespace eposp::canopen
