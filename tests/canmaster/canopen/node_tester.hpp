#pragma once

#include "sdo_test_support.hpp"
#include "service_bench.hpp"

#include <gtest/gtest.h>
#include <string>
#include <string_view>
#include <vector>

// The tester's side of a conformance test of a composed node (node-ID 5): it sends raw frames
// (candump form) on the bench and reads what the node put on the wire.

namespace eposp::canopen::testing {

/// One request of an SDO conversation and every frame the node sends before the next one.
struct SdoStep {
    std::string request;
    std::vector<std::string> replies;
};
struct SdoConversation {
    std::string name;
    std::vector<SdoStep> steps;
    friend void PrintTo(const SdoConversation& c, std::ostream* os) { *os << c.name; }
};

inline std::string conversation_name(const ::testing::TestParamInfo<SdoConversation>& info) {
    return info.param.name;
}

class NodeTester : public ::testing::Test {
protected:
    /// Sends `request` and returns what the node put on the wire in the next `window`.
    std::vector<std::string> exchange(std::string_view request,
                                      core::Duration window = std::chrono::milliseconds(2)) {
        const core::TimePoint from = bench.loop.now();
        bench.send(request);
        bench.run_for(window);
        return frames_since(from);
    }
    /// An exchange that must be answered by exactly `reply`.
    void expect_reply(std::string_view request, std::string_view reply) {
        EXPECT_EQ(exchange(request), std::vector<std::string>{std::string(reply)}) << request;
    }
    /// Every step of `conversation`, each answered as it says.
    void expect_conversation(const std::vector<SdoStep>& conversation) {
        for (const SdoStep& step : conversation) {
            EXPECT_EQ(exchange(step.request), step.replies) << step.request;
        }
    }
    /// An expedited SDO download to node 5 of the `size` low bytes of `value` that must succeed.
    void sdo_write(std::uint16_t index, std::uint8_t sub_index, std::uint32_t value,
                   std::size_t size) {
        const auto lo = static_cast<std::uint8_t>(index & 0xFF);
        const auto hi = static_cast<std::uint8_t>(index >> 8);
        Bytes request{static_cast<std::uint8_t>(0x23 | ((4 - size) << 2)), lo, hi, sub_index};
        const Bytes data = encode(value);
        request.insert(request.end(), data.begin(), data.end());
        expect_reply("605#" + hex(request),
                     "585#" + hex(Bytes{0x60, lo, hi, sub_index, 0, 0, 0, 0}));
    }
    std::vector<std::string> frames_since(core::TimePoint from, std::uint32_t only_id = 0) const {
        std::vector<std::string> out;
        for (const Sent& sent : sent_since(from, only_id)) {
            out.push_back(sent.frame);
        }
        return out;
    }
    std::vector<Sent> sent_since(core::TimePoint from, std::uint32_t only_id = 0) const {
        std::vector<Sent> out;
        for (const Sent& sent : bench.device_frames()) {
            if (sent.at >= from &&
                (only_id == 0 || can::parse_candump_frame(sent.frame)->id == only_id)) {
                out.push_back(sent);
            }
        }
        return out;
    }

    ServiceBench bench;
};

} // namespace eposp::canopen::testing
