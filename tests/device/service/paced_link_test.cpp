// Pacing in virtual time: a fake line records when each byte is handed to it.
#include "eposp/service/paced_link.hpp"
#include "link_test_support.hpp"

#include <gtest/gtest.h>
#include <numeric>
#include <vector>

namespace eposp::service {
namespace {

using namespace test;

/// A line that records the loop time at which each byte reaches it.
class FakeLine final : public Link {
public:
    explicit FakeLine(core::EventLoop& loop) : loop_(loop) {}
    void send(std::span<const std::uint8_t> bytes) override {
        for (std::uint8_t byte : bytes) {
            sent.push_back({loop_.now(), byte});
        }
    }
    std::string_view name() const override { return "fake"; }
    void receive(std::string_view text) { deliver(bytes_of(text)); }
    void hang_up() { report({LinkEvent::Kind::HungUp, "the host left"}); }

    struct Sent {
        core::TimePoint at;
        std::uint8_t byte;
    };
    std::vector<Sent> sent;

private:
    core::EventLoop& loop_;
};

class PacedLinkTest : public testing::Test {
protected:
    PacedLink& pace(LinkPacing pacing) {
        auto line_owned = std::make_unique<FakeLine>(loop);
        line = line_owned.get();
        auto wrapped = PacedLink::wrap(loop, std::move(line_owned), pacing);
        EXPECT_TRUE(wrapped) << wrapped.error();
        link = std::move(*wrapped);
        return *link;
    }

    static std::vector<std::uint8_t> counting(std::size_t n) {
        std::vector<std::uint8_t> bytes(n);
        std::iota(bytes.begin(), bytes.end(), std::uint8_t{0});
        return bytes;
    }

    core::EventLoop loop{core::Pace::Virtual};
    FakeLine* line = nullptr;
    std::unique_ptr<PacedLink> link;
};

TEST_F(PacedLinkTest, AtRs232RatesEachByteTakesTenBitTimes) {
    pace(LinkPacing::rs232()); // 115200 baud 8N1: 86.8 us a byte
    const core::TimePoint start = loop.now();
    const auto bytes = counting(1152);
    link->send(bytes);
    loop.run_for(99ms);
    EXPECT_LT(line->sent.size(), 1152u) << "not all gone before 100 ms";
    loop.run_for(1ms);
    ASSERT_EQ(line->sent.size(), 1152u);
    EXPECT_EQ(line->sent.back().at - start, 100ms) << "1152 bytes * 10 bits / 115200 bit/s";
    for (std::size_t k = 0; k < line->sent.size(); ++k) {
        const core::Duration due = LinkPacing::rs232().time_for(k + 1);
        ASSERT_EQ(line->sent[k].byte, bytes[k]) << "in order";
        ASSERT_GE(line->sent[k].at - start, due) << "byte " << k << " not before its last bit";
        ASSERT_LE(line->sent[k].at - start, due + 1ms) << "byte " << k << " at most a batch late";
    }
}

TEST_F(PacedLinkTest, OtherRatesScale) {
    EXPECT_EQ(LinkPacing::usb().time_for(100), 1ms) << "1 Mbit/s, 10 bits a byte";
    EXPECT_EQ(LinkPacing::rs232(9600).time_for(960), 1s);
    EXPECT_EQ(LinkPacing::rs232(115200).time_for(1), core::Duration(86806)) << "rounded up";
    EXPECT_EQ(LinkPacing::rs232(115200).time_for(11520), 1s) << "no drift over many bytes";

    pace(LinkPacing::usb());
    link->send(counting(100));
    loop.run_for(1ms);
    ASSERT_EQ(line->sent.size(), 100u);
    EXPECT_EQ(line->sent.back().at, core::TimePoint(1ms));
}

TEST_F(PacedLinkTest, BytesSentWhileTheLineIsBusyFollowWithoutAGap) {
    pace(LinkPacing::rs232(9600)); // 1.0417 ms a byte
    link->send(counting(10));
    loop.run_for(5ms);
    link->send(counting(10)); // the line is still busy with the first ten
    loop.run_for(1s);
    ASSERT_EQ(line->sent.size(), 20u);
    EXPECT_EQ(line->sent.back().at, core::TimePoint(LinkPacing::rs232(9600).time_for(20)));

    // Idle again: a new burst starts when it is sent.
    loop.run_until(core::TimePoint(2s));
    link->send(counting(1));
    loop.run_for(1s);
    EXPECT_EQ(line->sent.back().at, core::TimePoint(2s) + LinkPacing::rs232(9600).time_for(1));
}

TEST_F(PacedLinkTest, APacedLinkWakesTheLoopAboutOnceAMillisecond) {
    pace(LinkPacing::usb());
    link->send(counting(10000)); // 100 ms of line time
    const std::uint64_t events = loop.run_for(1s);
    EXPECT_EQ(line->sent.size(), 10000u);
    EXPECT_LE(events, 101u);
}

TEST_F(PacedLinkTest, WithoutPacingEverythingGoesAtOnce) {
    pace(LinkPacing::off());
    link->send(counting(1152));
    EXPECT_EQ(line->sent.size(), 1152u);
    EXPECT_EQ(line->sent.back().at, core::TimePoint{});
}

TEST_F(PacedLinkTest, ReceivedBytesAreHandedOnAtTheLineRateToo) {
    pace(LinkPacing::rs232());
    LinkRecorder recorder(*link);
    link->send(counting(100)); // a long answer on its way does not hold up what comes in
    line->receive("request");  // the pseudo-terminal carried it at once
    EXPECT_EQ(recorder.received, "");
    loop.run_for(LinkPacing::rs232().time_for(7) - 1ns);
    EXPECT_EQ(recorder.received, "") << "the last byte is still on the line (bytes due within "
                                        "1 ms are handed on together)";
    loop.run_for(1ns);
    EXPECT_EQ(recorder.received, "request");
    EXPECT_EQ(link->statistics().bytes_received, 7u);
}

TEST_F(PacedLinkTest, WithoutPacingReceivedBytesAreHandedOnAtOnce) {
    pace(LinkPacing::off());
    LinkRecorder recorder(*link);
    line->receive("request");
    EXPECT_EQ(recorder.received, "request");
}

TEST_F(PacedLinkTest, AHangUpDropsWhatTheHostSentAndTheLineHasNotCarriedYet) {
    pace(LinkPacing::rs232());
    LinkRecorder recorder(*link);
    line->receive("request");
    line->hang_up();
    loop.run_for(1s);
    EXPECT_EQ(recorder.received, "");
}

TEST_F(PacedLinkTest, AFullQueueDropsTheNewestBytesAndCountsThem) {
    LinkPacing pacing = LinkPacing::rs232();
    pacing.max_queued_bytes = 100;
    pace(pacing);
    link->send(counting(80));
    link->send(counting(50)); // 20 fit
    EXPECT_EQ(link->queued_bytes(), 100u);
    EXPECT_EQ(link->statistics().bytes_dropped_full, 30u);
    loop.run_for(1s);
    ASSERT_EQ(line->sent.size(), 100u);
    EXPECT_EQ(line->sent[79].byte, 79);
    EXPECT_EQ(line->sent[80].byte, 0) << "the first of the second send";
    EXPECT_EQ(line->sent[99].byte, 19);
}

TEST_F(PacedLinkTest, AHangUpDropsWhatWaitsForTheLine) {
    pace(LinkPacing::rs232());
    LinkRecorder recorder(*link);
    link->send(counting(1000));
    loop.run_for(10ms);
    const std::size_t before = line->sent.size();
    line->hang_up();
    ASSERT_EQ(recorder.events.size(), 1u);
    EXPECT_EQ(recorder.events[0].kind, LinkEvent::Kind::HungUp);
    EXPECT_EQ(link->queued_bytes(), 0u);
    EXPECT_EQ(link->statistics().bytes_dropped_no_host, 1000u - before);
    loop.run_for(1s);
    EXPECT_EQ(line->sent.size(), before);
}

TEST_F(PacedLinkTest, ARateOfZeroIsRefused) {
    LinkPacing pacing = LinkPacing::rs232(0);
    auto refused = PacedLink::wrap(loop, std::make_unique<FakeLine>(loop), pacing);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().find("line rate"), std::string::npos);
}

} // namespace
} // namespace eposp::service
