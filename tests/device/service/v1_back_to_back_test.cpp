// A v1 host link and a v1 device link wired to each other through byte queues, as the event
// loop delivers bytes: many random exchanges, with and without answers, and line noise.

#include "eposp/service/commands.hpp"
#include "eposp/service/v1_device_link.hpp"
#include "eposp/service/v1_host_link.hpp"
#include "random_frame.hpp"

#include <deque>
#include <gtest/gtest.h>

namespace eposp::service {
namespace {

using test::Bytes;

// The two ends and the bytes in flight between them. The device's owner answers each request
// with the frame `answer_for` gives, or not at all where v1 sends no answer.
class Wire {
public:
    explicit Wire(std::mt19937& random) : random_(random) {}

    V1Completion exchange(const Frame& request) {
        completions_.clear();
        host_.request(request, answered_on_v1(request.opcode));
        pump();
        EXPECT_EQ(completions_.size(), 1u);
        EXPECT_FALSE(host_.busy());
        EXPECT_FALSE(device_.mid_frame());
        return completions_.empty() ? V1Completion{} : completions_.front();
    }
    const std::vector<Frame>& requests() const { return requests_; }
    const std::vector<Frame>& answers() const { return answers_; }
    /// Flips one bit of the next byte the host sends once `after` more bytes went by.
    void corrupt_host_byte(std::size_t after) { corrupt_after_ = after; }

private:
    void pump() {
        while (!to_device_.empty() || !to_host_.empty()) {
            if (!to_device_.empty()) {
                const Bytes chunk{to_device_.front()};
                to_device_.pop_front();
                device_.receive(chunk);
            }
            if (!to_host_.empty()) {
                const Bytes chunk{to_host_.front()};
                to_host_.pop_front();
                host_.receive(chunk);
            }
        }
    }

    std::mt19937& random_;
    std::deque<std::uint8_t> to_device_;
    std::deque<std::uint8_t> to_host_;
    std::optional<std::size_t> corrupt_after_;
    std::vector<Frame> requests_;
    std::vector<Frame> answers_;
    std::vector<V1Completion> completions_;
    V1HostLink host_{[this](std::span<const std::uint8_t> out) {
                         for (std::uint8_t byte : out) {
                             if (corrupt_after_ && (*corrupt_after_)-- == 0) {
                                 byte ^= 0x04;
                                 corrupt_after_.reset();
                             }
                             to_device_.push_back(byte);
                         }
                     },
                     [this](const V1Completion& done) {
                         completions_.push_back(done);
                     }};
    V1DeviceLink device_{
        [this](std::span<const std::uint8_t> out) {
            to_host_.insert(to_host_.end(), out.begin(), out.end());
        },
        [this](const Frame& request) {
            requests_.push_back(request);
            if (!answered_on_v1(request.opcode)) {
                device_.skip_answer();
                return;
            }
            answers_.push_back(Frame{kAnswerOpCode, test::random_frame(random_, 1, 256).data});
            device_.send_answer(answers_.back());
        }};
};

// A request opcode v1 can carry: not 0x00 and not a handshake byte.
Frame random_request(std::mt19937& random) {
    Frame frame = test::random_frame(random, 1, 256, 0.05);
    while (!is_v1_request_opcode(frame.opcode)) {
        frame.opcode = static_cast<std::uint8_t>(random());
    }
    return frame;
}

TEST(V1BackToBack, ExchangesAThousandRandomFrames) {
    std::mt19937 random(1000);
    Wire wire(random);
    std::vector<Frame> sent;
    std::size_t unanswered = 0;
    for (int i = 0; i < 1000; ++i) {
        // Every tenth one is a request v1 does not answer (SendNMTService, SendCANFrame, ...).
        Frame request = random_request(random);
        if (i % 10 == 0) {
            request.opcode = 0x0E;
        }
        sent.push_back(request);
        const V1Completion done = wire.exchange(request);
        if (!answered_on_v1(request.opcode)) {
            ++unanswered;
            ASSERT_EQ(done.outcome, V1Outcome::Sent) << i;
            continue;
        }
        ASSERT_EQ(done.outcome, V1Outcome::Answered) << i;
        ASSERT_EQ(done.answer, wire.answers().back()) << i;
    }
    EXPECT_EQ(wire.requests(), sent);
    EXPECT_EQ(wire.answers().size(), sent.size() - unanswered);
}

TEST(V1BackToBack, ACorruptedByteIsACrcErrorAndTheNextExchangeWorks) {
    std::mt19937 random(7);
    Wire wire(random);
    const Frame request{0x10, test::bytes({0x41, 0x60, 0x00, 0x00})};
    wire.corrupt_host_byte(3); // a data byte of the request
    EXPECT_EQ(wire.exchange(request).outcome, V1Outcome::DeviceCrcError);
    EXPECT_TRUE(wire.requests().empty());
    EXPECT_EQ(wire.exchange(request).outcome, V1Outcome::Answered);
    EXPECT_EQ(wire.requests(), std::vector<Frame>{request});
}

// Without queues each link's write lands in the other's receive() at once, so every callback
// runs inside the other link's: the links update their state before they write.
TEST(V1BackToBack, LinksWiredDirectlyMayCallEachOtherFromTheirCallbacks) {
    std::mt19937 random(99);
    std::vector<V1Completion> completions;
    std::vector<Frame> answers;
    V1DeviceLink* device_end = nullptr;
    V1HostLink host([&](std::span<const std::uint8_t> out) { device_end->receive(out); },
                    [&](const V1Completion& done) { completions.push_back(done); });
    V1DeviceLink device([&](std::span<const std::uint8_t> out) { host.receive(out); },
                        [&](const Frame& request) {
                            if (!answered_on_v1(request.opcode)) {
                                device_end->skip_answer();
                                return;
                            }
                            answers.push_back(Frame{kAnswerOpCode, request.data});
                            device_end->send_answer(answers.back());
                        });
    device_end = &device;
    for (int i = 0; i < 100; ++i) {
        const Frame request = random_request(random);
        host.request(request, answered_on_v1(request.opcode));
        ASSERT_EQ(completions.size(), static_cast<std::size_t>(i + 1));
        const V1Completion& done = completions.back();
        if (answered_on_v1(request.opcode)) {
            ASSERT_EQ(done.outcome, V1Outcome::Answered) << i;
            ASSERT_EQ(done.answer, answers.back()) << i;
        } else {
            ASSERT_EQ(done.outcome, V1Outcome::Sent) << i;
        }
        ASSERT_FALSE(host.busy());
        ASSERT_FALSE(device.mid_frame());
    }
}

} // namespace
} // namespace eposp::service
