// The device side of the RS-232 link (v1): handshakes, answers and what it does where the host
// misbehaves (docs/service-interface.md, "Links and framing").

#include "eposp/service/v1_device_link.hpp"
#include "random_frame.hpp"
#include "v1_vectors.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::service {
namespace {

using test::Bytes;
using test::bytes;

using test::kAnswer;
using test::kAnswerRest;
using test::kReadStatusword;
using test::kReadStatuswordRest;

// A device link whose output and requests are recorded; the test plays the host.
struct Device {
    Bytes written;
    std::vector<Frame> requests;
    V1DeviceLink link{[this](std::span<const std::uint8_t> out) {
                          written.insert(written.end(), out.begin(), out.end());
                      },
                      [this](const Frame& frame) {
                          requests.push_back(frame);
                      }};

    /// What the device writes in answer to `in`.
    Bytes host_sends(const Bytes& in) {
        written.clear();
        link.receive(in);
        return written;
    }
    /// Sends the guide's ReadObject request, acknowledged at both steps.
    void take_read_request() {
        ASSERT_EQ(host_sends({0x10}), bytes({'O'}));
        ASSERT_EQ(host_sends(kReadStatuswordRest), bytes({'O'}));
    }
    Bytes answer(const Frame& frame) {
        written.clear();
        link.send_answer(frame);
        return written;
    }
};

TEST(V1DeviceLink, TakesTheGuidesReadObjectRequestAndSendsItsAnswerByteForByte) {
    Device device;
    device.take_read_request();
    EXPECT_EQ(device.requests, std::vector<Frame>{kReadStatusword});
    EXPECT_TRUE(device.link.awaiting_answer());
    EXPECT_FALSE(device.link.mid_frame()) << "the owner's time to answer is not a frame timeout";

    EXPECT_EQ(device.answer(kAnswer), bytes({0x00}));
    EXPECT_TRUE(device.link.mid_frame());
    EXPECT_EQ(device.host_sends({'O'}), kAnswerRest);
    EXPECT_EQ(device.host_sends({'O'}), Bytes{});
    EXPECT_FALSE(device.link.mid_frame());
    EXPECT_EQ(device.link.counters().answers_sent, 1u);

    device.take_read_request(); // ready for the next one
    EXPECT_EQ(device.requests.size(), 2u);
}

TEST(V1DeviceLink, AnswersFToAWrongCrcAndDropsTheRequest) {
    Device device;
    Bytes corrupt = kReadStatuswordRest;
    corrupt.back() ^= 0x80;
    ASSERT_EQ(device.host_sends({0x10}), bytes({'O'}));
    EXPECT_EQ(device.host_sends(corrupt), bytes({'F'}));
    EXPECT_TRUE(device.requests.empty());
    EXPECT_FALSE(device.link.mid_frame());
    EXPECT_EQ(device.link.counters().crc_errors, 1u);
    device.take_read_request();
    EXPECT_EQ(device.requests, std::vector<Frame>{kReadStatusword});
}

TEST(V1DeviceLink, RefusesARequestWhileTheLastOneIsStillBeingProcessed) {
    Device device;
    device.take_read_request();
    EXPECT_EQ(device.host_sends({0x10}), bytes({'F'}));
    EXPECT_EQ(device.link.counters().refused_busy, 1u);
    EXPECT_TRUE(device.link.awaiting_answer()) << "the refused opcode changes nothing";
    EXPECT_EQ(device.answer(kAnswer), bytes({0x00}));
}

TEST(V1DeviceLink, RefusesARequestWhileItsAnswerWaitsForTheHost) {
    Device device;
    device.take_read_request();
    device.answer(kAnswer);
    EXPECT_EQ(device.host_sends({0x11}), bytes({'F'}));
    EXPECT_EQ(device.host_sends({'O'}), kAnswerRest) << "the answer goes on";
    EXPECT_EQ(device.host_sends({0x11}), bytes({'F'}));
    EXPECT_EQ(device.host_sends({'O'}), Bytes{});
    EXPECT_EQ(device.link.counters().refused_busy, 2u);
    EXPECT_EQ(device.link.counters().answers_sent, 1u);
}

TEST(V1DeviceLink, HostNotReadyForTheAnswerLosesIt) {
    Device device;
    device.take_read_request();
    device.answer(kAnswer);
    EXPECT_EQ(device.host_sends({'F'}), Bytes{});
    EXPECT_FALSE(device.link.mid_frame());
    EXPECT_EQ(device.link.counters().answers_lost, 1u);
    device.take_read_request();
}

TEST(V1DeviceLink, HostCrcErrorOnTheAnswerLosesItWithoutResending) {
    Device device;
    device.take_read_request();
    device.answer(kAnswer);
    ASSERT_EQ(device.host_sends({'O'}), kAnswerRest);
    EXPECT_EQ(device.host_sends({'F'}), Bytes{}) << "maxon's hosts do not expect a resend";
    EXPECT_FALSE(device.link.mid_frame());
    EXPECT_EQ(device.link.counters().answers_lost, 1u);
    device.take_read_request();
}

TEST(V1DeviceLink, SkippedAnswerReturnsToIdle) {
    Device device;
    // SendNMTService (0x0E) gets no answer on v1: the owner skips it.
    const Frame nmt{0x0E, bytes({0x00, 0x00, 0x01, 0x00})};
    ASSERT_EQ(device.host_sends({0x0E}), bytes({'O'}));
    ASSERT_EQ(device.host_sends(v1_frame_rest(nmt)), bytes({'O'}));
    ASSERT_EQ(device.requests, std::vector<Frame>{nmt});
    device.link.skip_answer();
    EXPECT_FALSE(device.link.awaiting_answer());
    device.take_read_request();
}

TEST(V1DeviceLink, AnswerOrSkipWithoutARequestIsAProgrammingError) {
    Device device;
    EXPECT_THROW(device.link.send_answer(kAnswer), std::logic_error);
    EXPECT_THROW(device.link.skip_answer(), std::logic_error);
    device.take_read_request();
    EXPECT_THROW(device.link.send_answer(Frame{0x00, {}}), std::invalid_argument);
    EXPECT_TRUE(device.link.awaiting_answer()) << "a refused answer leaves the request open";
}

TEST(V1DeviceLink, TimeoutMidRequestDropsItAndWaitsForAnOpcode) {
    Device device;
    ASSERT_EQ(device.host_sends({0x10, 0x01, 0x41}), bytes({'O'}));
    ASSERT_TRUE(device.link.mid_frame());
    device.link.on_timeout();
    EXPECT_FALSE(device.link.mid_frame());
    EXPECT_EQ(device.link.counters().timeouts, 1u);
    device.take_read_request();
    EXPECT_EQ(device.requests, std::vector<Frame>{kReadStatusword});
}

TEST(V1DeviceLink, TimeoutWhileTheAnswerWaitsForTheHostLosesIt) {
    Device device;
    device.take_read_request();
    device.answer(kAnswer);
    device.link.on_timeout();
    EXPECT_FALSE(device.link.mid_frame());
    EXPECT_EQ(device.link.counters().answers_lost, 1u);
    EXPECT_EQ(device.host_sends({'O'}), Bytes{}) << "a late 'O' is ignored";
    device.take_read_request();
}

TEST(V1DeviceLink, TimeoutWhileTheOwnerProcessesChangesNothing) {
    Device device;
    device.take_read_request();
    device.link.on_timeout();
    EXPECT_TRUE(device.link.awaiting_answer());
    EXPECT_EQ(device.link.counters().timeouts, 0u);
}

TEST(V1DeviceLink, IgnoresHandshakeBytesAndTheAnswerOpcodeWhileIdle) {
    Device device;
    EXPECT_EQ(device.host_sends({'O', 'F', 0x00, 'O'}), Bytes{});
    EXPECT_EQ(device.link.counters().ignored_bytes, 4u);
    EXPECT_FALSE(device.link.mid_frame());
}

TEST(V1DeviceLink, GarbageTakenForARequestEndsInACrcErrorOrATimeout) {
    Device device;
    // 0x55 is taken for an opcode, 0x00 for Len-1 (one word), then the word and a wrong CRC.
    EXPECT_EQ(device.host_sends({0x55}), bytes({'O'}));
    EXPECT_EQ(device.host_sends({0x00, 0x12, 0x34, 0x56, 0x78}), bytes({'F'}));
    // A stalled piece of garbage waits for the frame timeout.
    EXPECT_EQ(device.host_sends({0x77, 0x05}), bytes({'O'}));
    device.link.on_timeout();
    device.take_read_request();
    EXPECT_EQ(device.requests, std::vector<Frame>{kReadStatusword});
}

TEST(V1DeviceLink, CarriesMaxSizeFramesOf256WordsBothWays) {
    std::mt19937 random(256);
    const Frame request{0x15, test::random_frame(random, 256, 256).data};
    const Frame answer{0x00, test::random_frame(random, 256, 256).data};
    const Bytes rest = v1_frame_rest(request);
    ASSERT_EQ(rest.front(), 0xFF) << "Len-1 of 256 words";
    Device device;
    ASSERT_EQ(device.host_sends({request.opcode}), bytes({'O'}));
    EXPECT_EQ(device.host_sends(rest), bytes({'O'}));
    EXPECT_EQ(device.requests, std::vector<Frame>{request});
    device.answer(answer);
    EXPECT_EQ(device.host_sends({'O'}), v1_frame_rest(answer));
    EXPECT_THROW(v1_frame_rest(Frame{0x00, Bytes(2 * 257)}), std::invalid_argument);
}

} // namespace
} // namespace eposp::service
