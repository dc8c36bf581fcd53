// The host side of the RS-232 link (v1), as the service clients use it: the bytes it sends and
// how each request ends (docs/service-interface.md, "Links and framing").

#include "eposp/service/v1_host_link.hpp"
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

// A host link whose output and completions are recorded; the test plays the device.
struct Host {
    Bytes written;
    std::vector<V1Completion> completions;
    V1HostLink link{[this](std::span<const std::uint8_t> out) {
                        written.insert(written.end(), out.begin(), out.end());
                    },
                    [this](const V1Completion& done) {
                        completions.push_back(done);
                    }};

    Bytes request(const Frame& frame, bool expect_answer = true) {
        written.clear();
        link.request(frame, expect_answer);
        return written;
    }
    Bytes device_sends(const Bytes& in) {
        written.clear();
        link.receive(in);
        return written;
    }
    V1Outcome outcome() const {
        EXPECT_EQ(completions.size(), 1u);
        return completions.empty() ? V1Outcome::Timeout : completions.back().outcome;
    }
};

TEST(V1HostLink, SendsTheGuidesReadObjectRequestAndTakesItsAnswerByteForByte) {
    Host host;
    EXPECT_EQ(host.request(kReadStatusword), bytes({0x10}));
    EXPECT_EQ(host.device_sends({'O'}), kReadStatuswordRest);
    EXPECT_EQ(host.device_sends({'O'}), Bytes{});
    EXPECT_TRUE(host.link.awaiting_answer());
    EXPECT_EQ(host.device_sends({0x00}), bytes({'O'}));
    EXPECT_FALSE(host.link.awaiting_answer());
    EXPECT_EQ(host.device_sends(kAnswerRest), bytes({'O'}));
    ASSERT_EQ(host.outcome(), V1Outcome::Answered);
    EXPECT_EQ(host.completions.back().answer, kAnswer);
    EXPECT_FALSE(host.link.busy());
}

TEST(V1HostLink, ARequestWithoutAnswerCompletesAtTheDevicesFinalO) {
    Host host;
    const Frame nmt{0x0E, bytes({0x00, 0x00, 0x01, 0x00})};
    EXPECT_EQ(host.request(nmt, false), bytes({0x0E}));
    EXPECT_EQ(host.device_sends({'O'}), v1_frame_rest(nmt));
    host.device_sends({'O'});
    EXPECT_EQ(host.outcome(), V1Outcome::Sent);
    EXPECT_FALSE(host.link.busy());
}

TEST(V1HostLink, DeviceNotReadyEndsTheRequest) {
    Host host;
    host.request(kReadStatusword);
    EXPECT_EQ(host.device_sends({'F'}), Bytes{}) << "the rest of the frame is not sent";
    EXPECT_EQ(host.outcome(), V1Outcome::DeviceNotReady);
    EXPECT_FALSE(host.link.busy());
}

TEST(V1HostLink, DeviceCrcErrorEndsTheRequest) {
    Host host;
    host.request(kReadStatusword);
    host.device_sends({'O'});
    host.device_sends({'F'});
    EXPECT_EQ(host.outcome(), V1Outcome::DeviceCrcError);
}

TEST(V1HostLink, AnswerWithAWrongCrcIsRefusedWithF) {
    Host host;
    host.request(kReadStatusword);
    host.device_sends({'O', 'O', 0x00});
    Bytes corrupt = kAnswerRest;
    corrupt[5] ^= 0x01;
    EXPECT_EQ(host.device_sends(corrupt), bytes({'F'}));
    EXPECT_EQ(host.outcome(), V1Outcome::AnswerCrcError);
    EXPECT_FALSE(host.completions.back().answer.has_value());
}

TEST(V1HostLink, AByteOutOfPlaceEndsTheRequest) {
    Host host;
    host.request(kReadStatusword);
    host.device_sends({'O', 'O', 0x37}); // not the answer opcode
    EXPECT_EQ(host.outcome(), V1Outcome::UnexpectedByte);
}

TEST(V1HostLink, TimeoutAtEachStepEndsTheRequestOnce) {
    // The device stalls after 0, 1, 2, 3 and 3 + 5 bytes of the exchange.
    const std::vector<Bytes> stalls{
        {}, {'O'}, {'O', 'O'}, {'O', 'O', 0x00}, bytes({'O', 'O', 0x00, 0x03, 0, 0, 0, 0})};
    for (const Bytes& before : stalls) {
        Host host;
        host.request(kReadStatusword);
        host.device_sends(before);
        ASSERT_TRUE(host.link.busy());
        host.link.on_timeout();
        EXPECT_EQ(host.outcome(), V1Outcome::Timeout);
        host.link.on_timeout();
        EXPECT_EQ(host.completions.size(), 1u) << "a timeout while idle completes nothing";
        EXPECT_FALSE(host.link.busy());
    }
}

TEST(V1HostLink, IgnoresBytesWhileIdleAndRefusesASecondRequest) {
    Host host;
    host.device_sends({'O', 0x00});
    EXPECT_EQ(host.link.stray_bytes(), 2u);
    EXPECT_TRUE(host.completions.empty());
    host.request(kReadStatusword);
    EXPECT_THROW(host.link.request(kReadStatusword), std::logic_error);
    EXPECT_THROW(Host{}.link.request(Frame{0x10, {}}), std::invalid_argument);
}

TEST(V1HostLink, TheCompletionMaySendTheNextRequest) {
    Bytes written;
    int done = 0;
    V1HostLink* self = nullptr;
    V1HostLink link(
        [&](std::span<const std::uint8_t> out) {
            written.insert(written.end(), out.begin(), out.end());
        },
        [&](const V1Completion&) {
            if (++done == 1) {
                self->request(kReadStatusword);
            }
        });
    self = &link;
    link.request(kReadStatusword);
    link.receive(bytes({'F'}));
    EXPECT_EQ(written, bytes({0x10, 0x10}));
    EXPECT_TRUE(link.busy());
}

} // namespace
} // namespace eposp::service
