#pragma once

#include "eposp/can/virtual_bus.hpp"

#include <string>
#include <vector>

namespace eposp::can::testing {

/// A WireEvent that owns its sender's name.
struct RecordedEvent {
    core::TimePoint start;
    core::TimePoint end;
    Frame frame;
    std::string sender;
};

/// Everything an observer of the bus saw, in order.
class WireLog {
public:
    explicit WireLog(VirtualBus& bus) {
        bus.add_observer([this](const WireEvent& event) {
            events.push_back({event.start, event.end, event.frame, std::string(event.sender)});
        });
    }
    std::vector<std::uint32_t> ids() const {
        std::vector<std::uint32_t> out;
        for (const RecordedEvent& event : events) {
            out.push_back(event.frame.id);
        }
        return out;
    }
    std::vector<RecordedEvent> events;
};

/// The frames a port received, with the loop time at which each arrived.
struct Inbox {
    explicit Inbox(Port& port, const core::EventLoop& loop) {
        port.on_receive([this, &loop](const Frame& frame) {
            frames.push_back(frame);
            times.push_back(loop.now());
        });
    }
    std::vector<Frame> frames;
    std::vector<core::TimePoint> times;
};

inline core::TimePoint at_us(std::int64_t microseconds) {
    return core::TimePoint{std::chrono::microseconds(microseconds)};
}

} // namespace eposp::can::testing
