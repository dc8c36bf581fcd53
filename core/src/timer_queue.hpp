#pragma once

#include "eposp/core/event_loop.hpp"

#include <optional>
#include <queue>
#include <unordered_map>
#include <vector>

namespace eposp::core {

/// The pending events of an EventLoop: a binary heap ordered by (time, scheduling sequence)
/// with cancellation by id. Cancelled entries are dropped lazily when they reach the top.
class TimerQueue {
public:
    struct Due {
        TimerId id;
        TimePoint when;
    };

    TimerId schedule(TimePoint when, Duration period, EventLoop::Callback fn);
    bool cancel(TimerId id);
    bool pending(TimerId id) const { return entries_.contains(id.value); }
    std::size_t size() const { return entries_.size(); }

    /// The earliest live event, if any.
    std::optional<TimePoint> next_time();

    /// Runs the earliest live event: `set_now` is told its time first. A periodic event is
    /// re-armed one period after its scheduled time unless its callback cancelled it.
    /// Precondition: next_time() has a value.
    void run_next(const std::function<void(TimePoint)>& set_now);

private:
    struct Slot {
        TimePoint when;
        std::uint64_t sequence;
        std::uint64_t id;
        bool operator>(const Slot& other) const {
            return when != other.when ? when > other.when : sequence > other.sequence;
        }
    };
    struct Entry {
        EventLoop::Callback fn;
        Duration period; // zero for one-shot timers
    };

    void push(TimePoint when, std::uint64_t id);
    void drop_cancelled();

    std::priority_queue<Slot, std::vector<Slot>, std::greater<>> heap_;
    std::unordered_map<std::uint64_t, Entry> entries_;
    std::uint64_t next_id_ = 1;
    std::uint64_t next_sequence_ = 0;
};

} // namespace eposp::core
