#pragma once

#include "eposp/can/frame.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace eposp::can {

enum class FrameFault { Drop, Corrupt, Shorten };

/// The frame faults injected into a virtual bus, each with the frames it still has to take.
class FrameFaults {
public:
    using Filter = std::function<bool(const Frame&)>;

    std::uint64_t add(FrameFault fault, Filter filter, std::uint64_t count);
    bool cancel(std::uint64_t id);
    /// The fault the frame starting on the wire suffers: the first one added that matches it.
    /// That fault then has one frame fewer to take. Inline for the usual bus without faults.
    std::optional<FrameFault> take(const Frame& frame) {
        return entries_.empty() ? std::nullopt : take_matching(frame);
    }

private:
    std::optional<FrameFault> take_matching(const Frame& frame);

    struct Entry {
        std::uint64_t id;
        FrameFault fault;
        Filter filter;
        std::uint64_t remaining;
    };
    std::vector<Entry> entries_;
    std::uint64_t next_id_ = 1;
};

} // namespace eposp::can
