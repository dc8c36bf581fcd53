#include "sdo_test_support.hpp"

#include <gtest/gtest.h>
#include <vector>

// Conformance tests of the SDO server (CiA 301 7.2.4): the tester sends raw request frames to
// node 5 and checks every reply byte for byte. Abort frames read "585#80 iiii ss cccccccc" with
// index and abort code little-endian.

namespace eposp::canopen {
namespace {

using namespace testing;

TEST(SdoProtocol, BlockCrcIsCrc16CcittWithInitialValueZero) {
    const std::string_view check = "123456789";
    const Bytes data(check.begin(), check.end());
    EXPECT_EQ(sdo::block_crc(data), 0x31C3); // the published check value of CRC-16/XMODEM
    EXPECT_EQ(sdo::block_crc({}), 0x0000);
}

TEST(SdoProtocol, CommandBytesFollowCiA301) {
    EXPECT_EQ(sdo::initiate_command(sdo::ccs::kInitiateDownload, 1, true, true), 0x27);
    EXPECT_EQ(sdo::initiate_command(sdo::scs::kInitiateUpload, 0, false, true), 0x41);
    EXPECT_EQ(sdo::segment_command(sdo::scs::kUploadSegment, true, 2, true), 0x15);
    EXPECT_EQ(sdo::segment_command(sdo::ccs::kUploadSegment, true), 0x70);
    EXPECT_EQ(sdo::block_initiate_command(sdo::ccs::kBlockDownload, true, true), 0xC6);
    EXPECT_EQ(sdo::block_end_command(sdo::scs::kBlockUpload, 2), 0xC9);
    EXPECT_EQ(sdo::block_command(sdo::ccs::kBlockUpload, sdo::block::kStartUpload), 0xA3);
    EXPECT_EQ(sdo::block_segment_command(3, true), 0x83);
    EXPECT_EQ(sdo::block_subcommand(0xC6), sdo::block::kInitiate); // bit 1 is "size indicated"
    EXPECT_EQ(sdo::block_subcommand(0xA2), sdo::block::kAcknowledge);
}

// Expedited transfers (CiA 301 7.2.4.3.3 / 7.2.4.3.6).

TEST(SdoServer, ExpeditedUploadSendsTheValueWithItsSize) {
    SdoServerBench bench;
    bench.od.set_as<std::uint8_t>(0x2000, 0, 0xAB);
    bench.od.set_as<std::uint16_t>(0x2001, 0, 0x1234);
    EXPECT_EQ(bench.exchange("605#4000100000000000"), Replies{"585#4300100092010200"});
    EXPECT_EQ(bench.exchange("605#4001200000000000"), Replies{"585#4B01200034120000"});
    EXPECT_EQ(bench.exchange("605#4000200000000000"), Replies{"585#4F002000AB000000"});
}

TEST(SdoServer, AnswersInTheFrameSlotAfterTheRequest) {
    SdoServerBench bench;
    const std::string request = "605#4000100000000000";
    bench.send(request);
    bench.run_for(10ms);
    EXPECT_EQ(bench.device_frames(),
              (std::vector<Sent>{{next_slot(at_us(0), request), "585#4300100092010200"}}));
}

TEST(SdoServer, ExpeditedDownloadWritesTheIndicatedBytes) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#2B01200034120000"), Replies{"585#6001200000000000"});
    EXPECT_EQ(bench.od.get_as<std::uint16_t>(0x2001, 0), 0x1234);
    EXPECT_EQ(bench.exchange("605#2302200078563412"), Replies{"585#6002200000000000"});
    EXPECT_EQ(bench.od.get_as<std::uint32_t>(0x2002, 0), 0x12345678U);
}

TEST(SdoServer, ExpeditedDownloadWithoutSizeTakesTheObjectsSize) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#2201200078560000"), Replies{"585#6001200000000000"});
    EXPECT_EQ(bench.od.get_as<std::uint16_t>(0x2001, 0), 0x5678);
}

// Segmented transfers (CiA 301 7.2.4.3.4 / 7.2.4.3.7).

TEST(SdoServer, SegmentedUploadTogglesAndEndsWithTheLastSegment) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#4008100000000000"), Replies{"585#410810000C000000"});
    EXPECT_EQ(bench.exchange("605#6000000000000000"), Replies{"585#0045504F53322032"});
    EXPECT_EQ(bench.exchange("605#7000000000000000"), Replies{"585#15342F3520580000"});
    EXPECT_FALSE(bench.server.busy());
}

TEST(SdoServer, EmptyValueUploadsAsOneEmptySegment) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#4000210000000000"), Replies{"585#4100210000000000"});
    EXPECT_EQ(bench.exchange("605#6000000000000000"), Replies{"585#0F00000000000000"});
}

TEST(SdoServer, SegmentedDownloadStoresTheValueAfterTheLastSegment) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#210021000A000000"), Replies{"585#6000210000000000"});
    EXPECT_EQ(bench.exchange("605#0001020304050607"), Replies{"585#2000000000000000"});
    EXPECT_TRUE(bench.od.get(0x2100, 0).empty()) << "stored only when complete";
    EXPECT_EQ(bench.exchange("605#1908090A00000000"), Replies{"585#3000000000000000"});
    EXPECT_EQ(bench.od.get(0x2100, 0), counting_bytes(10));
}

// A download that ends before its value is whole tells the object why (CiA 302-3: a device
// reports an interrupted program download); one that handed its value over does not.
class SdoServerInterruptedDownload : public ::testing::Test {
protected:
    SdoServerInterruptedDownload() {
        bench.od.find(0x2100, 0)->on_write_aborted = [this](AbortCode reason) {
            reasons.push_back(reason);
        };
        EXPECT_EQ(bench.exchange("605#210021000A000000"), Replies{"585#6000210000000000"});
        EXPECT_EQ(bench.exchange("605#0001020304050607"), Replies{"585#2000000000000000"});
    }
    SdoServerBench bench;
    std::vector<AbortCode> reasons;
};

TEST_F(SdoServerInterruptedDownload, TheClientsAbortIsTold) {
    bench.exchange("605#8000210005000405"); // 0x05040005
    EXPECT_EQ(reasons, std::vector{AbortCode::OutOfMemory});
}

TEST_F(SdoServerInterruptedDownload, ATimeoutIsTold) {
    bench.loop.run_for(std::chrono::seconds(2));
    EXPECT_EQ(reasons, std::vector{AbortCode::SdoTimeout});
}

TEST_F(SdoServerInterruptedDownload, ANewRequestEndsItAndIsTold) {
    bench.exchange("605#4000100000000000");
    EXPECT_EQ(reasons, std::vector{AbortCode::CommandSpecifier});
}

TEST_F(SdoServerInterruptedDownload, AWrongToggleIsTold) {
    bench.exchange("605#0001020304050607"); // toggle 0 again
    EXPECT_EQ(reasons, std::vector{AbortCode::ToggleBit});
}

TEST_F(SdoServerInterruptedDownload, AValueHandedOverIsNotAnInterruption) {
    bench.exchange("605#1908090A00000000");
    bench.exchange("605#4000100000000000");
    EXPECT_TRUE(reasons.empty());
}

TEST(SdoServer, SegmentedDownloadWithoutSizeIndicator) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#2006200000000000"), Replies{"585#6006200000000000"});
    EXPECT_EQ(bench.exchange("605#0941424300000000"), Replies{"585#2000000000000000"});
    const Bytes abc = encode_string("ABC");
    EXPECT_EQ(bench.od.get(0x2006, 0), abc);
}

TEST(SdoServer, SegmentedDownloadToAnExpeditedSizedObject) {
    SdoServerBench bench; // CiA 301 lets a client send any value segmented
    EXPECT_EQ(bench.exchange("605#2102200004000000"), Replies{"585#6002200000000000"});
    EXPECT_EQ(bench.exchange("605#0778563412000000"), Replies{"585#2000000000000000"});
    EXPECT_EQ(bench.od.get_as<std::uint32_t>(0x2002, 0), 0x12345678U);
}

// Every abort code of the dictionary travels back unchanged (CiA 301 7.2.4.3.17).

struct AbortCase {
    const char* name;
    const char* request;
    const char* reply;
};

void PrintTo(const AbortCase& c, std::ostream* os) {
    *os << c.name;
}

class SdoServerDictionaryAbort : public ::testing::TestWithParam<AbortCase> {};

TEST_P(SdoServerDictionaryAbort, ReachesTheClientUnchanged) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange(GetParam().request), Replies{GetParam().reply});
    EXPECT_FALSE(bench.server.busy());
}

INSTANTIATE_TEST_SUITE_P(
    Table, SdoServerDictionaryAbort,
    ::testing::Values(
        AbortCase{"UploadMissingObject", "605#4000300000000000", "585#8000300000000206"},
        AbortCase{"UploadMissingSubIndex", "605#4000200100000000", "585#8000200111000906"},
        AbortCase{"UploadWriteOnly", "605#4005200000000000", "585#8005200001000106"},
        AbortCase{"DownloadReadOnly", "605#2300100001000000", "585#8000100002000106"},
        AbortCase{"DownloadConst", "605#2F08100041000000", "585#8008100002000106"},
        AbortCase{"DownloadMissingObject", "605#2F00300001000000", "585#8000300000000206"},
        AbortCase{"DownloadTooLong", "605#2301200001020304", "585#8001200012000706"},
        AbortCase{"DownloadTooShort", "605#2B02200001020000", "585#8002200013000706"},
        AbortCase{"DownloadAboveRange", "605#23032000E9030000", "585#8003200031000906"},
        AbortCase{"DownloadBelowRange", "605#2303200009000000", "585#8003200032000906"},
        AbortCase{"DownloadRefusedByWriteHook", "605#2307200000000000", "585#8007200022000008"},
        AbortCase{"SegmentedDownloadReadOnly", "605#2100100008000000", "585#8000100002000106"},
        AbortCase{"SegmentedDownloadIndicatesTooMuch", "605#2102200008000000",
                  "585#8002200012000706"},
        AbortCase{"SegmentedDownloadIndicatesTooLittle", "605#2104200004000000",
                  "585#8004200013000706"},
        AbortCase{"SegmentedUploadMissingObject", "605#4000300100000000", "585#8000300100000206"}),
    [](const auto& row) { return std::string(row.param.name); });

// Size indicator against the data that came (CiA 301 7.2.4.3.3: s, n).

TEST(SdoServer, MoreDataThanIndicatedAbortsAtTheSegmentThatOverflows) {
    SdoServerBench bench;
    bench.exchange("605#210021000A000000");
    EXPECT_EQ(bench.exchange("605#0001020304050607"), Replies{"585#2000000000000000"});
    EXPECT_EQ(bench.exchange("605#1008090A0B0C0D0E"), Replies{"585#8000210012000706"});
    EXPECT_TRUE(bench.od.get(0x2100, 0).empty());
}

TEST(SdoServer, LessDataThanIndicatedAbortsAtTheLastSegment) {
    SdoServerBench bench;
    bench.exchange("605#210021000A000000");
    EXPECT_EQ(bench.exchange("605#0101020304050607"), Replies{"585#8000210013000706"});
    EXPECT_TRUE(bench.od.get(0x2100, 0).empty());
}

TEST(SdoServer, UnindicatedDownloadAbortsOnceItOutgrowsTheObject) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#2002200000000000"), Replies{"585#6002200000000000"});
    EXPECT_EQ(bench.exchange("605#0001020304050607"), Replies{"585#8002200012000706"});
}

TEST(SdoServer, DomainTakesAnySizeUpToItsMaximumLength) {
    SdoServerBench bench;
    bench.od.find(0x2100, 0)->max_length = 16;
    EXPECT_EQ(bench.exchange("605#2100210011000000"), Replies{"585#8000210012000706"});
    EXPECT_EQ(bench.exchange("605#2100210010000000"), Replies{"585#6000210000000000"});
}

// Protocol violations by the client.

TEST(SdoServer, WrongToggleInADownloadSegmentAborts) {
    SdoServerBench bench;
    bench.exchange("605#210021000A000000");
    EXPECT_EQ(bench.exchange("605#1001020304050607"), Replies{"585#8000210000000305"});
    EXPECT_FALSE(bench.server.busy());
}

TEST(SdoServer, WrongToggleInAnUploadSegmentRequestAborts) {
    SdoServerBench bench;
    bench.exchange("605#4008100000000000");
    bench.exchange("605#6000000000000000");
    EXPECT_EQ(bench.exchange("605#6000000000000000"), Replies{"585#8008100000000305"});
}

TEST(SdoServer, UnknownCommandSpecifierAborts) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#E000100000000000"), Replies{"585#8000100001000405"});
}

TEST(SdoServer, SegmentWithoutATransferAborts) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#6000000000000000"), Replies{"585#8000000001000405"});
    EXPECT_EQ(bench.exchange("605#0001020304050607"), Replies{"585#8001020301000405"})
        << "idle, so the abort echoes bytes 1..3 of the request";
}

TEST(SdoServer, RequestOfTheOtherDirectionDuringATransferAborts) {
    SdoServerBench bench;
    bench.exchange("605#210021000A000000");
    EXPECT_EQ(bench.exchange("605#6000000000000000"), Replies{"585#8000210001000405"});
    EXPECT_FALSE(bench.server.busy());
}

TEST(SdoServer, AbortFromTheClientEndsTheTransferSilently) {
    SdoServerBench bench;
    bench.exchange("605#210021000A000000");
    EXPECT_EQ(bench.exchange("605#8000210000000008"), Replies{});
    EXPECT_FALSE(bench.server.busy());
    EXPECT_EQ(bench.exchange("605#0001020304050607"), Replies{"585#8001020301000405"});
}

TEST(SdoServer, AbortWhileIdleIsNotAnswered) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#8000100000000008"), Replies{});
}

TEST(SdoServer, NewInitiateEndsTheRunningTransferAndIsServed) {
    SdoServerBench bench;
    bench.exchange("605#4008100000000000");
    bench.exchange("605#6000000000000000");
    EXPECT_EQ(bench.exchange("605#4000100000000000"), Replies{"585#4300100092010200"});
    EXPECT_EQ(bench.exchange("605#7000000000000000"), Replies{"585#8000000001000405"});
}

TEST(SdoServer, NewDownloadDuringADownloadStartsOver) {
    SdoServerBench bench;
    bench.exchange("605#210021000A000000");
    bench.exchange("605#0001020304050607");
    EXPECT_EQ(bench.exchange("605#2100210008000000"), Replies{"585#6000210000000000"});
    EXPECT_EQ(bench.exchange("605#0009090909090909"), Replies{"585#2000000000000000"});
    EXPECT_EQ(bench.exchange("605#1D09000000000000"), Replies{"585#3000000000000000"});
    EXPECT_EQ(bench.od.get(0x2100, 0), Bytes(8, 9));
}

// Timeouts on the event loop (CiA 301 7.2.4.3.17: 0x05040000).

TEST(SdoServer, TransferWithoutProgressTimesOutAfterOneSecond) {
    SdoServerBench bench;
    const std::string request = "605#210021000A000000";
    bench.send(request);
    bench.run_for(2s);
    const auto received = end_of(at_us(0), request);
    EXPECT_EQ(bench.device_frames(), (std::vector<Sent>{{received + 3us, "585#6000210000000000"},
                                                        {received + 1s, "585#8000210000000405"}}));
    EXPECT_FALSE(bench.server.busy());
}

TEST(SdoServer, EachSegmentRestartsTheTimeout) {
    SdoServerBench bench;
    bench.send("605#210021000A000000");
    bench.run_for(900ms);
    const std::string segment = "605#0001020304050607";
    bench.send(segment);
    bench.run_until(at_ms(1800));
    EXPECT_TRUE(bench.server.busy());
    bench.run_until(at_ms(2000));
    const auto frames = bench.device_frames();
    ASSERT_EQ(frames.size(), 3U);
    EXPECT_EQ(frames[2], (Sent{end_of(at_ms(900), segment) + 1s, "585#8000210000000405"}));
}

TEST(SdoServer, TimeoutIsConfigurable) {
    SdoServerBench bench(SdoServerConfig{.timeout = 50ms});
    const std::string request = "605#4008100000000000";
    bench.send(request);
    bench.run_for(100ms);
    const auto frames = bench.device_frames();
    ASSERT_EQ(frames.size(), 2U);
    EXPECT_EQ(frames[1], (Sent{end_of(at_us(0), request) + 50ms, "585#8008100000000405"}));
}

TEST(SdoServer, ExpeditedTransfersStartNoTimer) {
    SdoServerBench bench;
    bench.exchange("605#4000100000000000");
    EXPECT_EQ(bench.loop.pending_count(), 0U);
}

// NMT state and frame filtering.

struct NmtCase {
    const char* name;
    NmtState state;
    bool answers;
};

void PrintTo(const NmtCase& c, std::ostream* os) {
    *os << c.name;
}

class SdoServerNmt : public ::testing::TestWithParam<NmtCase> {};

TEST_P(SdoServerNmt, AnswersOnlyInPreOperationalAndOperational) {
    SdoServerBench bench;
    bench.server.set_nmt_state(GetParam().state);
    EXPECT_EQ(bench.exchange("605#4000100000000000").size(), GetParam().answers ? 1U : 0U);
}

INSTANTIATE_TEST_SUITE_P(States, SdoServerNmt,
                         ::testing::Values(NmtCase{"Initialising", NmtState::Initialising, false},
                                           NmtCase{"PreOperational", NmtState::PreOperational,
                                                   true},
                                           NmtCase{"Operational", NmtState::Operational, true},
                                           NmtCase{"Stopped", NmtState::Stopped, false}),
                         [](const auto& row) { return std::string(row.param.name); });

TEST(SdoServer, StoppingDropsTheRunningTransferWithoutAReply) {
    SdoServerBench bench;
    bench.exchange("605#210021000A000000");
    bench.server.set_nmt_state(NmtState::Stopped);
    bench.run_for(2s);
    EXPECT_EQ(bench.device_frames().size(), 1U) << "no timeout abort either";
    bench.server.set_nmt_state(NmtState::PreOperational);
    EXPECT_EQ(bench.exchange("605#0001020304050607"), Replies{"585#8001020301000405"});
}

TEST(SdoServer, IgnoresFramesThatAreNotItsRequests) {
    SdoServerBench bench;
    EXPECT_EQ(bench.exchange("605#40001000000000"), Replies{}) << "7 bytes";
    EXPECT_EQ(bench.exchange("605#R"), Replies{}) << "remote frame";
    EXPECT_EQ(bench.exchange("606#4000100000000000"), Replies{}) << "another node";
    EXPECT_EQ(bench.exchange("00000605#4000100000000000"), Replies{}) << "29-bit identifier";
    EXPECT_EQ(bench.exchange("585#4000100000000000"), Replies{}) << "a response";
}

// The server parameter object (CiA 301 7.5.2.33, EPOS2 firmware specification 8.2.17).

TEST(SdoServerObjects, ServerParameterHoldsTheDefaultCobIdsReadOnly) {
    SdoServerBench bench;
    EXPECT_EQ(bench.od.get_as<std::uint8_t>(0x1200, 0), 2);
    EXPECT_EQ(bench.od.get_as<std::uint32_t>(0x1200, 1), 0x605U);
    EXPECT_EQ(bench.od.get_as<std::uint32_t>(0x1200, 2), 0x585U);
    EXPECT_EQ(bench.exchange("605#4000120200000000"), Replies{"585#4300120285050000"});
    EXPECT_EQ(bench.exchange("605#2300120106060000"), Replies{"585#8000120102000106"});
    EXPECT_EQ(bench.server.request_cob_id(), 0x605U);
    EXPECT_EQ(bench.server.response_cob_id(), 0x585U);
}

} // namespace
} // namespace eposp::canopen
