#include "sdo_test_support.hpp"

#include <gtest/gtest.h>
#include <memory>

// The SDO client (CiA 301 7.2.4): against a raw-frame server played by the tester, which checks
// every request byte for byte and misbehaves on purpose; then round trips with real servers.

namespace eposp::canopen {
namespace {

using namespace testing;

// Expedited and segmented transfers with a well-behaved server.

TEST(SdoClient, ExpeditedUploadCompletesWithTheValue) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1000, 0, outcome.upload());
    EXPECT_EQ(outcome.calls, 0);
    EXPECT_EQ(bench.settle(), Replies{"605#4000100000000000"});
    EXPECT_EQ(bench.exchange("585#4300100092010200"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::None);
    EXPECT_EQ(outcome.value, encode<std::uint32_t>(0x0002'0192));
    EXPECT_FALSE(bench.client.busy(kServerNode));
}

TEST(SdoClient, ExpeditedUploadWithoutSizeTakesFourBytes) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1000, 0, outcome.upload());
    bench.settle();
    bench.exchange("585#4200100092010200");
    EXPECT_EQ(outcome.value, encode<std::uint32_t>(0x0002'0192));
}

TEST(SdoClient, DownloadsOfUpToFourBytesAreExpedited) {
    SdoClientBench bench;
    Outcome one;
    Outcome four;
    bench.client.download(kServerNode, 0x2000, 0, {0xAB}, one.download());
    bench.client.download(kServerNode, 0x2002, 0, encode<std::uint32_t>(0x12345678),
                          four.download(), {.protocol = SdoProtocol::Block});
    EXPECT_EQ(bench.settle(), Replies{"605#2F002000AB000000"});
    EXPECT_EQ(bench.exchange("585#6000200000000000"), Replies{"605#2302200078563412"});
    EXPECT_EQ(bench.exchange("585#6002200000000000"), Replies{});
    EXPECT_EQ(one.code, AbortCode::None);
    EXPECT_EQ(four.code, AbortCode::None);
}

TEST(SdoClient, FourByteDownloadWithoutSizeLeavesTheLengthToTheServer) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.download(kServerNode, 0x6040, 0, encode<std::uint32_t>(0x000F), outcome.download(),
                          {.size_indicated = false});
    EXPECT_EQ(bench.settle(), Replies{"605#224060000F000000"});
    EXPECT_EQ(bench.exchange("585#6040600000000000"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::None);
}

TEST(SdoClient, SegmentedDownloadTogglesUntilTheLastSegment) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.download(kServerNode, 0x2100, 0, counting_bytes(10), outcome.download());
    EXPECT_EQ(bench.settle(), Replies{"605#210021000A000000"});
    EXPECT_EQ(bench.exchange("585#6000210000000000"), Replies{"605#0001020304050607"});
    EXPECT_EQ(bench.exchange("585#2000000000000000"), Replies{"605#1908090A00000000"});
    EXPECT_FALSE(outcome.code);
    EXPECT_EQ(bench.exchange("585#3000000000000000"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::None);
}

TEST(SdoClient, EmptyDownloadIsOneEmptySegment) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.download(kServerNode, 0x2100, 0, {}, outcome.download());
    EXPECT_EQ(bench.settle(), Replies{"605#2100210000000000"});
    EXPECT_EQ(bench.exchange("585#6000210000000000"), Replies{"605#0F00000000000000"});
    bench.exchange("585#2000000000000000");
    EXPECT_EQ(outcome.code, AbortCode::None);
}

TEST(SdoClient, SegmentedUploadTogglesUntilTheLastSegment) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1008, 0, outcome.upload());
    EXPECT_EQ(bench.settle(), Replies{"605#4008100000000000"});
    EXPECT_EQ(bench.exchange("585#410810000C000000"), Replies{"605#6000000000000000"});
    EXPECT_EQ(bench.exchange("585#0045504F53322032"), Replies{"605#7000000000000000"});
    EXPECT_EQ(bench.exchange("585#15342F3520580000"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::None);
    EXPECT_EQ(outcome.value, encode_string(kDeviceName));
}

TEST(SdoClient, SegmentedUploadWithoutSizeIndicator) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1008, 0, outcome.upload());
    bench.settle();
    EXPECT_EQ(bench.exchange("585#4008100000000000"), Replies{"605#6000000000000000"});
    bench.exchange("585#0945504F00000000");
    EXPECT_EQ(outcome.value, encode_string("EPO"));
}

// A misbehaving server: the client aborts with the right code, tells the server and the
// callback.

struct Violation {
    const char* name;
    bool upload;
    std::vector<const char*> server_frames; ///< the client aborts on the last one
    const char* client_abort;
    AbortCode code;
};

void PrintTo(const Violation& c, std::ostream* os) {
    *os << c.name;
}

class SdoClientViolation : public ::testing::TestWithParam<Violation> {};

TEST_P(SdoClientViolation, AbortsTheTransferWithTheCode) {
    const Violation& c = GetParam();
    SdoClientBench bench(SdoClientConfig{.max_upload_size = 64});
    Outcome outcome;
    if (c.upload) {
        bench.client.upload(kServerNode, 0x2100, 0, outcome.upload());
    } else {
        bench.client.download(kServerNode, 0x2100, 0, counting_bytes(10), outcome.download());
    }
    bench.settle();
    Replies last;
    for (const char* frame : c.server_frames) {
        last = bench.exchange(frame);
    }
    EXPECT_EQ(last, Replies{c.client_abort});
    EXPECT_EQ(outcome.code, c.code);
    EXPECT_EQ(outcome.calls, 1);
    EXPECT_TRUE(outcome.value.empty());
    EXPECT_FALSE(bench.client.busy(kServerNode));
}

INSTANTIATE_TEST_SUITE_P(
    Table, SdoClientViolation,
    ::testing::Values(
        Violation{"DownloadWrongToggle",
                  false,
                  {"585#6000210000000000", "585#3000000000000000"},
                  "605#8000210000000305",
                  AbortCode::ToggleBit},
        Violation{"UploadWrongToggle",
                  true,
                  {"585#410021000A000000", "585#1001020304050607"},
                  "605#8000210000000305",
                  AbortCode::ToggleBit},
        Violation{"DownloadWrongIndexEcho",
                  false,
                  {"585#6001210000000000"},
                  "605#8000210000000008",
                  AbortCode::GeneralError},
        Violation{"DownloadWrongSubIndexEcho",
                  false,
                  {"585#6000210100000000"},
                  "605#8000210000000008",
                  AbortCode::GeneralError},
        Violation{"UploadWrongIndexEcho",
                  true,
                  {"585#4300200001020304"},
                  "605#8000210000000008",
                  AbortCode::GeneralError},
        Violation{"UploadAnsweredAsDownload",
                  true,
                  {"585#6000210000000000"},
                  "605#8000210001000405",
                  AbortCode::CommandSpecifier},
        Violation{"DownloadAnsweredAsUpload",
                  false,
                  {"585#4300210001020304"},
                  "605#8000210001000405",
                  AbortCode::CommandSpecifier},
        Violation{"UnknownServerCommand",
                  true,
                  {"585#E000210000000000"},
                  "605#8000210001000405",
                  AbortCode::CommandSpecifier},
        Violation{"DownloadSegmentAnsweredAsUploadSegment",
                  false,
                  {"585#6000210000000000", "585#0000000000000000"},
                  "605#8000210001000405",
                  AbortCode::CommandSpecifier},
        Violation{"UploadMoreThanIndicated",
                  true,
                  {"585#410021000A000000", "585#0001020304050607", "585#1008090A0B0C0D0E"},
                  "605#8000210012000706",
                  AbortCode::LengthTooHigh},
        Violation{"UploadLessThanIndicated",
                  true,
                  {"585#410021000A000000", "585#0101020304050607"},
                  "605#8000210013000706",
                  AbortCode::LengthTooLow},
        Violation{"UploadIndicatesMoreThanTheClientTakes",
                  true,
                  {"585#4100210041000000"},
                  "605#8000210005000405",
                  AbortCode::OutOfMemory},
        Violation{"UploadGrowsBeyondWhatTheClientTakes",
                  true,
                  {"585#4000210000000000", "585#0001020304050607", "585#1001020304050607",
                   "585#0001020304050607", "585#1001020304050607", "585#0001020304050607",
                   "585#1001020304050607", "585#0001020304050607", "585#1001020304050607",
                   "585#0001020304050607", "585#1001020304050607"},
                  "605#8000210005000405",
                  AbortCode::OutOfMemory}),
    [](const auto& row) { return std::string(row.param.name); });

TEST(SdoClient, ServerAbortReachesTheCallbackUnanswered) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x3000, 0, outcome.upload());
    bench.settle();
    EXPECT_EQ(bench.exchange("585#8000300000000206"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::ObjectDoesNotExist);
}

TEST(SdoClient, ServerAbortInTheMiddleOfASegmentedDownload) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.download(kServerNode, 0x2100, 0, counting_bytes(10), outcome.download());
    bench.settle();
    bench.exchange("585#6000210000000000");
    EXPECT_EQ(bench.exchange("585#8000210022000008"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::DeviceState);
}

TEST(SdoClient, ServerAbortWithoutACodeIsAGeneralError) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1000, 0, outcome.upload());
    bench.settle();
    bench.exchange("585#8000100000000000");
    EXPECT_EQ(outcome.code, AbortCode::GeneralError);
}

// CiA 301 7.2.4.3.9 / 7.2.4.3.13: a server without block transfer aborts the block initiate
// with 0x05040001; the client asks again, segmented.

TEST(SdoClient, BlockDownloadRefusedByTheServerIsRetriedSegmented) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.download(kServerNode, 0x2100, 0, counting_bytes(10), outcome.download(),
                          {.protocol = SdoProtocol::Block});
    EXPECT_EQ(bench.settle(), Replies{"605#C60021000A000000"});
    EXPECT_EQ(bench.exchange("585#8000210001000405"), Replies{"605#210021000A000000"});
    EXPECT_EQ(bench.exchange("585#6000210000000000"), Replies{"605#0001020304050607"});
    EXPECT_EQ(bench.exchange("585#2000000000000000"), Replies{"605#1908090A00000000"});
    EXPECT_EQ(bench.exchange("585#3000000000000000"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::None);
    EXPECT_EQ(outcome.calls, 1);
}

TEST(SdoClient, BlockUploadRefusedByTheServerIsRetriedSegmented) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x2100, 0, outcome.upload(), {.protocol = SdoProtocol::Block});
    EXPECT_EQ(bench.settle(), Replies{"605#A40021007F040000"});
    EXPECT_EQ(bench.exchange("585#8000210001000405"), Replies{"605#4000210000000000"});
    EXPECT_EQ(bench.exchange("585#4300210078563412"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::None);
    EXPECT_EQ(outcome.value, encode<std::uint32_t>(0x1234'5678));
}

TEST(SdoClient, OtherAbortsOfABlockInitiateEndTheTransfer) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x2100, 0, outcome.upload(), {.protocol = SdoProtocol::Block});
    bench.settle();
    EXPECT_EQ(bench.exchange("585#8000210000000206"), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::ObjectDoesNotExist);
}

// Timeouts in virtual time.

TEST(SdoClient, SilentServerTimesOutAfterOneSecond) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1000, 0, outcome.upload());
    bench.run_for(999ms);
    EXPECT_FALSE(outcome.code);
    bench.run_for(2s);
    const std::string request = "605#4000100000000000";
    EXPECT_EQ(bench.device_frames(),
              (std::vector<Sent>{{at_us(0), request}, {at_us(0) + 1s, "605#8000100000000405"}}));
    EXPECT_EQ(outcome.code, AbortCode::SdoTimeout);
}

TEST(SdoClient, EachResponseRestartsTheTimeout) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1008, 0, outcome.upload());
    bench.run_for(800ms);
    bench.send("585#410810000C000000"); // arrives about 800.1 ms
    bench.run_until(at_ms(1700));
    EXPECT_FALSE(outcome.code);
    bench.run_until(at_ms(1900));
    EXPECT_EQ(outcome.code, AbortCode::SdoTimeout);
}

TEST(SdoClient, TimeoutIsConfigurablePerClientAndPerRequest) {
    SdoClientBench bench(SdoClientConfig{.timeout = 100ms});
    Outcome short_one;
    Outcome long_one;
    bench.client.upload(kServerNode, 0x1000, 0, short_one.upload());
    bench.client.upload(6, 0x1000, 0, long_one.upload(), {.timeout = 5s});
    bench.run_for(150ms);
    EXPECT_EQ(short_one.code, AbortCode::SdoTimeout);
    EXPECT_FALSE(long_one.code);
    bench.run_for(5s);
    EXPECT_EQ(long_one.code, AbortCode::SdoTimeout);
}

// Queueing, concurrency and cancellation.

TEST(SdoClient, RequestsToOneServerRunOneAtATimeInOrder) {
    SdoClientBench bench;
    std::vector<int> order;
    for (int i = 0; i < 3; ++i) {
        bench.client.upload(kServerNode, 0x1000, 0,
                            [&order, i](AbortCode, Bytes) { order.push_back(i); });
    }
    EXPECT_EQ(bench.client.pending(kServerNode), 3U);
    EXPECT_EQ(bench.settle(), Replies{"605#4000100000000000"});
    EXPECT_EQ(bench.exchange("585#4300100092010200"), Replies{"605#4000100000000000"});
    EXPECT_EQ(bench.exchange("585#4300100092010200"), Replies{"605#4000100000000000"});
    EXPECT_EQ(bench.exchange("585#4300100092010200"), Replies{});
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(bench.client.pending(kServerNode), 0U);
}

TEST(SdoClient, ServersAreServedAtTheSameTime) {
    SdoClientBench bench;
    Outcome five;
    Outcome six;
    bench.client.upload(5, 0x1000, 0, five.upload());
    bench.client.upload(6, 0x1000, 0, six.upload());
    EXPECT_EQ(bench.settle(), (Replies{"605#4000100000000000", "606#4000100000000000"}));
    EXPECT_TRUE(bench.client.busy(5));
    EXPECT_TRUE(bench.client.busy(6));
    bench.exchange("586#4300100006000000");
    bench.exchange("585#4300100005000000");
    EXPECT_EQ(five.value, encode<std::uint32_t>(5));
    EXPECT_EQ(six.value, encode<std::uint32_t>(6));
}

TEST(SdoClient, AbortedTransferLetsTheNextRequestRun) {
    SdoClientBench bench;
    Outcome first;
    Outcome second;
    bench.client.upload(kServerNode, 0x3000, 0, first.upload());
    bench.client.upload(kServerNode, 0x1000, 0, second.upload());
    bench.settle();
    EXPECT_EQ(bench.exchange("585#8000300000000206"), Replies{"605#4000100000000000"});
    EXPECT_EQ(first.code, AbortCode::ObjectDoesNotExist);
}

TEST(SdoClient, CallbackMayQueueTheNextRequest) {
    SdoClientBench bench;
    Outcome second;
    bench.client.upload(kServerNode, 0x1000, 0, [&](AbortCode, Bytes) {
        bench.client.upload(kServerNode, 0x1008, 0, second.upload());
    });
    bench.settle();
    EXPECT_EQ(bench.exchange("585#4300100092010200"), Replies{"605#4008100000000000"});
}

TEST(SdoClient, CancellingAQueuedRequestNeverSendsIt) {
    SdoClientBench bench;
    Outcome first;
    Outcome second;
    bench.client.upload(kServerNode, 0x1000, 0, first.upload());
    const SdoRequestId id = bench.client.upload(kServerNode, 0x1008, 0, second.upload());
    EXPECT_TRUE(bench.client.cancel(id, AbortCode::LocalControl));
    EXPECT_FALSE(bench.client.cancel(id));
    EXPECT_EQ(second.code, AbortCode::LocalControl);
    EXPECT_EQ(bench.settle(), Replies{"605#4000100000000000"});
    EXPECT_EQ(bench.exchange("585#4300100092010200"), Replies{});
    EXPECT_EQ(second.calls, 1);
}

TEST(SdoClient, CancellingTheRunningRequestAbortsItOnTheBus) {
    SdoClientBench bench;
    Outcome first;
    Outcome second;
    const SdoRequestId id = bench.client.upload(kServerNode, 0x1008, 0, first.upload());
    bench.client.upload(kServerNode, 0x1000, 0, second.upload());
    bench.settle();
    EXPECT_TRUE(bench.client.cancel(id, AbortCode::LocalControl));
    EXPECT_EQ(first.code, AbortCode::LocalControl);
    EXPECT_EQ(bench.settle(), (Replies{"605#8008100021000008", "605#4000100000000000"}));
    EXPECT_EQ(bench.exchange("585#410810000C000000"), Replies{"605#8000100000000008"})
        << "a late response of the cancelled transfer names another object";
}

TEST(SdoClient, CancelAllEndsEveryRequestOfANodeThatDisappeared) {
    SdoClientBench bench;
    std::vector<AbortCode> codes;
    for (int i = 0; i < 3; ++i) {
        bench.client.upload(kServerNode, 0x1000, 0,
                            [&codes](AbortCode code, Bytes) { codes.push_back(code); });
    }
    Outcome other;
    bench.client.upload(6, 0x1000, 0, other.upload());
    bench.settle();
    EXPECT_EQ(bench.client.cancel_all(kServerNode, AbortCode::SdoTimeout), 3U);
    EXPECT_EQ(codes, std::vector<AbortCode>(3, AbortCode::SdoTimeout));
    EXPECT_EQ(bench.settle(), Replies{"605#8000100000000405"});
    EXPECT_EQ(bench.client.pending(kServerNode), 0U);
    EXPECT_TRUE(bench.client.busy(6));
    EXPECT_EQ(bench.client.cancel_all(7), 0U);
}

// Configuration and frame filtering.

TEST(SdoClient, CobIdsPerServerAreConfigurable) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.set_cob_ids(kServerNode, 0x2000'0000 | 0x1234567, 0x2000'0000 | 0x1234568);
    bench.client.upload(kServerNode, 0x1000, 0, outcome.upload());
    EXPECT_EQ(bench.settle(), Replies{"01234567#4000100000000000"});
    bench.exchange("585#4300100092010200");
    EXPECT_FALSE(outcome.code) << "not on the configured COB-ID";
    bench.exchange("01234568#4300100092010200");
    EXPECT_EQ(outcome.code, AbortCode::None);
}

TEST(SdoClient, InvalidCobIdFailsTheRequestsAfterTheCall) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.set_cob_ids(kServerNode, 0x8000'0605, 0x8000'0585);
    bench.client.upload(kServerNode, 0x1000, 0, outcome.upload());
    EXPECT_EQ(outcome.calls, 0) << "never from inside upload()";
    EXPECT_EQ(bench.settle(), Replies{});
    EXPECT_EQ(outcome.code, AbortCode::ResourceNotAvailable);
}

TEST(SdoClient, ChangingCobIdsEndsTheRunningTransfer) {
    SdoClientBench bench;
    Outcome first;
    Outcome second;
    bench.client.upload(kServerNode, 0x1000, 0, first.upload());
    bench.client.upload(kServerNode, 0x1000, 0, second.upload());
    bench.settle();
    bench.client.set_cob_ids(kServerNode, 0x615, 0x595);
    EXPECT_EQ(first.code, AbortCode::ResourceNotAvailable);
    EXPECT_EQ(bench.settle(), (Replies{"605#8000100023000A06", "615#4000100000000000"}));
}

TEST(SdoClient, IgnoresFramesThatAreNoResponseOfItsTransfer) {
    SdoClientBench bench;
    Outcome outcome;
    bench.client.upload(kServerNode, 0x1000, 0, outcome.upload());
    bench.settle();
    EXPECT_EQ(bench.exchange("585#43001000920102"), Replies{}) << "7 bytes";
    EXPECT_EQ(bench.exchange("586#4300100092010200"), Replies{}) << "another server";
    EXPECT_EQ(bench.exchange("605#4300100092010200"), Replies{}) << "a request";
    EXPECT_EQ(bench.exchange("585#R"), Replies{}) << "remote frame";
    EXPECT_FALSE(outcome.code);
    bench.exchange("585#4300100092010200");
    EXPECT_EQ(outcome.code, AbortCode::None);
}

TEST(SdoClient, ResponsesWhileIdleAreIgnored) {
    SdoClientBench bench;
    EXPECT_EQ(bench.exchange("585#4300100092010200"), Replies{});
}

TEST(SdoClient, NodeIdMustBeOneTo127) {
    SdoClientBench bench;
    EXPECT_THROW(bench.client.upload(0, 0x1000, 0, {}), std::invalid_argument);
    EXPECT_THROW(bench.client.upload(128, 0x1000, 0, {}), std::invalid_argument);
}

// Round trips: the client against real servers on one bus.

/// A node with an SDO server and the test objects; its DOMAIN takes 100 kB and more.
struct ServerNode {
    ServerNode(core::EventLoop& loop, can::VirtualBus& bus, NodeId node)
        : port(bus.connect(fmt::format("node{}", node))), server(loop, *port, od, node) {
        add_sdo_test_objects(od);
        od.find(0x2100, 0)->max_length = 256 * 1024;
        port->on_receive([this](const can::Frame& frame) { server.on_frame(frame); });
    }

    std::unique_ptr<can::VirtualPort> port;
    ObjectDictionary od;
    SdoServer server;
};

/// A master port with an SDO client and servers on nodes 2, 3 and 4.
struct Network {
    explicit Network(std::initializer_list<NodeId> nodes = {2, 3, 4}) {
        master->on_receive([this](const can::Frame& frame) { client.on_frame(frame); });
        for (const NodeId node : nodes) {
            servers.push_back(std::make_unique<ServerNode>(loop, bus, node));
        }
    }

    /// Runs until every request completed (or a minute of bus time passed).
    void run() {
        for (int i = 0; i < 600 && client_busy(); ++i) {
            loop.run_for(100ms);
        }
    }
    bool client_busy() const {
        for (NodeId node = 1; node < 128; ++node) {
            if (client.pending(node) != 0) {
                return true;
            }
        }
        return false;
    }

    core::EventLoop loop;
    can::VirtualBus bus{loop};
    can::testing::WireLog wire{bus};
    std::unique_ptr<can::VirtualPort> master = bus.connect("master");
    SdoClient client{loop, *master};
    std::vector<std::unique_ptr<ServerNode>> servers;
};

struct RoundTrip {
    const char* name;
    std::size_t size;
    SdoProtocol protocol;
};

void PrintTo(const RoundTrip& c, std::ostream* os) {
    *os << c.name;
}

class SdoRoundTrip : public ::testing::TestWithParam<RoundTrip> {};

TEST_P(SdoRoundTrip, DomainValueTravelsBothWays) {
    Network net;
    const Bytes value = counting_bytes(GetParam().size);
    const SdoRequestOptions options{.protocol = GetParam().protocol,
                                    .protocol_switch_threshold = 0};
    Outcome written;
    Outcome read;
    net.client.download(3, 0x2100, 0, value, written.download(), options);
    net.client.upload(3, 0x2100, 0, read.upload(), options);
    net.run();
    EXPECT_EQ(written.code, AbortCode::None);
    EXPECT_EQ(net.servers[1]->od.get(0x2100, 0), value);
    EXPECT_EQ(read.code, AbortCode::None);
    EXPECT_EQ(read.value, value);
}

INSTANTIATE_TEST_SUITE_P(Sizes, SdoRoundTrip,
                         ::testing::Values(RoundTrip{"Segmented1", 1, SdoProtocol::Segmented},
                                           RoundTrip{"Segmented4", 4, SdoProtocol::Segmented},
                                           RoundTrip{"Segmented7", 7, SdoProtocol::Segmented},
                                           RoundTrip{"Segmented8", 8, SdoProtocol::Segmented},
                                           RoundTrip{"Segmented889", 889, SdoProtocol::Segmented},
                                           RoundTrip{"Segmented100k", 100'000,
                                                     SdoProtocol::Segmented},
                                           RoundTrip{"Block1", 1, SdoProtocol::Block},
                                           RoundTrip{"Block4", 4, SdoProtocol::Block},
                                           RoundTrip{"Block7", 7, SdoProtocol::Block},
                                           RoundTrip{"Block8", 8, SdoProtocol::Block},
                                           RoundTrip{"Block889", 889, SdoProtocol::Block},
                                           RoundTrip{"Block100k", 100'000, SdoProtocol::Block}),
                         [](const auto& row) { return std::string(row.param.name); });

TEST(SdoRoundTripValues, TypedValuesAndStrings) {
    Network net;
    Outcome u8;
    Outcome u64;
    Outcome text;
    Outcome name;
    net.client.download(2, 0x2000, 0, {0x7E}, u8.download());
    net.client.download(2, 0x2004, 0, encode<std::uint64_t>(0x0102030405060708), u64.download());
    net.client.download(2, 0x2006, 0, encode_string("Hello, EPOS P"), text.download());
    net.client.upload(2, 0x1008, 0, name.upload());
    net.run();
    EXPECT_EQ(u8.code, AbortCode::None);
    EXPECT_EQ(u64.code, AbortCode::None);
    EXPECT_EQ(text.code, AbortCode::None);
    EXPECT_EQ(net.servers[0]->od.get_as<std::uint8_t>(0x2000, 0), 0x7E);
    EXPECT_EQ(net.servers[0]->od.get_as<std::uint64_t>(0x2004, 0), 0x0102030405060708U);
    EXPECT_EQ(net.servers[0]->od.get(0x2006, 0), encode_string("Hello, EPOS P"));
    EXPECT_EQ(name.value, encode_string(kDeviceName));
}

TEST(SdoRoundTripValues, AbortCodesOfTheServersDictionaryReachTheCallback) {
    Network net;
    Outcome missing;
    Outcome read_only;
    Outcome too_long;
    Outcome refused;
    net.client.upload(2, 0x3000, 0, missing.upload());
    net.client.download(3, 0x1000, 0, encode<std::uint32_t>(1), read_only.download());
    net.client.download(4, 0x2001, 0, counting_bytes(8), too_long.download(),
                        {.protocol = SdoProtocol::Block});
    net.client.download(4, 0x2007, 0, encode<std::uint32_t>(0), refused.download());
    net.run();
    EXPECT_EQ(missing.code, AbortCode::ObjectDoesNotExist);
    EXPECT_EQ(read_only.code, AbortCode::ReadOnly);
    EXPECT_EQ(too_long.code, AbortCode::LengthTooHigh);
    EXPECT_EQ(refused.code, AbortCode::DeviceState);
}

TEST(SdoRoundTripValues, SeveralServersTransferAtOnce) {
    Network net;
    std::vector<Outcome> outcomes(3);
    for (std::size_t i = 0; i < 3; ++i) {
        net.client.download(static_cast<NodeId>(2 + i), 0x2100, 0, counting_bytes(100 + i),
                            outcomes[i].download());
    }
    net.run();
    std::vector<std::uint32_t> requesters;
    for (const auto& event : net.wire.events) {
        if (event.sender == "master" && requesters.size() < 3) {
            requesters.push_back(event.frame.id);
        }
    }
    EXPECT_EQ(requesters, (std::vector<std::uint32_t>{0x602, 0x603, 0x604}))
        << "the three transfers interleave";
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(outcomes[i].code, AbortCode::None);
        EXPECT_EQ(net.servers[i]->od.get(0x2100, 0), counting_bytes(100 + i));
    }
}

TEST(SdoRoundTripValues, AllOf127ServersAnswerOneClient) {
    std::vector<NodeId> ids;
    for (NodeId node = 1; node <= 127; ++node) {
        ids.push_back(node);
    }
    Network net({});
    for (const NodeId node : ids) {
        net.servers.push_back(std::make_unique<ServerNode>(net.loop, net.bus, node));
        net.servers.back()->od.set_as<std::uint32_t>(0x2002, 0, node);
    }
    std::vector<Outcome> outcomes(127);
    for (const NodeId node : ids) {
        net.client.upload(node, 0x2002, 0, outcomes[node - 1].upload());
    }
    net.run();
    for (const NodeId node : ids) {
        EXPECT_EQ(outcomes[node - 1].value, encode<std::uint32_t>(node)) << "node " << int{node};
    }
}

TEST(SdoRoundTripValues, BlockUploadOfASmallValueSwitchesToExpedited) {
    Network net;
    Outcome outcome;
    net.client.upload(2, 0x1000, 0, outcome.upload(), {.protocol = SdoProtocol::Block});
    net.run();
    EXPECT_EQ(outcome.value, encode<std::uint32_t>(0x0002'0192));
    ASSERT_EQ(net.wire.events.size(), 2U);
    EXPECT_EQ(net.wire.events[1].frame.data[0], 0x43);
}

} // namespace
} // namespace eposp::canopen
