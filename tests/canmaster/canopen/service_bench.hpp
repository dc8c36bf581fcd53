#pragma once

#include "eposp/can/candump_format.hpp"
#include "eposp/can/frame_timing.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "can/virtual_bus_test_support.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

// Conformance-style tests of the CANopen services: a device port carries the services under
// test, a tester port sends raw request frames, and the wire log shows every frame, its bytes
// (in candump form, "701#05") and the time it started on the wire.

namespace eposp::canopen {

/// GoogleTest prints NMT states by name.
inline void PrintTo(NmtState state, std::ostream* os) {
    *os << to_string(state);
}

} // namespace eposp::canopen

namespace eposp::canopen::testing {

inline core::TimePoint at_ms(std::int64_t milliseconds) {
    return core::TimePoint{std::chrono::milliseconds(milliseconds)};
}
using can::testing::at_us;

/// The earliest start of a frame sent the moment a frame that ended at `end` was received:
/// 3 bits of intermission later, at the bench's 1 Mbit/s.
inline core::TimePoint after_intermission(core::TimePoint end) {
    return end + std::chrono::microseconds(can::kIntermissionBits);
}

/// Longer than any frame at 1 Mbit/s: the wire log has a frame once it has ended, so a test
/// that wants a frame sent at t runs until t + kFrameTime.
inline constexpr core::Duration kFrameTime = std::chrono::microseconds(200);

/// One frame a port put on the wire: when it started and its bytes.
struct Sent {
    core::TimePoint at;
    std::string frame;

    friend bool operator==(const Sent&, const Sent&) = default;
    friend void PrintTo(const Sent& sent, std::ostream* os) {
        *os << core::format_seconds_micros(sent.at) << " " << sent.frame;
    }
};

inline std::string candump(const can::Frame& frame) {
    return can::format_candump_frame(frame);
}

/// A 1 Mbit/s bus with a "device" port and a "tester" port.
struct ServiceBench {
    core::EventLoop loop;
    can::VirtualBus bus{loop};
    can::testing::WireLog wire{bus};
    std::unique_ptr<can::VirtualPort> device = bus.connect("device");
    std::unique_ptr<can::VirtualPort> tester = bus.connect("tester");

    /// Everything `sender` put on the wire so far, in order.
    std::vector<Sent> sent_by(std::string_view sender) const {
        std::vector<Sent> out;
        for (const auto& event : wire.events) {
            if (event.sender == sender) {
                out.push_back({event.start, candump(event.frame)});
            }
        }
        return out;
    }
    std::vector<Sent> device_frames() const { return sent_by("device"); }

    /// The tester sends `frame` (parsed from candump form) now.
    void send(std::string_view frame) { tester->send(*can::parse_candump_frame(frame)); }
    void run_until(core::TimePoint t) { loop.run_until(t); }
    void run_for(core::Duration d) { loop.run_for(d); }
};

/// A remote write with its little-endian value, as an SDO download would make it.
template <typename T>
AbortCode write_as(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index, T value) {
    return od.write(index, sub_index, encode(value));
}

} // namespace eposp::canopen::testing
