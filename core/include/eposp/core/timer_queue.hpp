#pragma once

#include "eposp/core/time.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace eposp::core {

/// Identifies a scheduled callback so that it can be cancelled. The value 0 is never used.
struct TimerId {
    std::uint64_t value = 0;
    explicit operator bool() const { return value != 0; }
    friend bool operator==(TimerId, TimerId) = default;
};

/// The pending events of an EventLoop (its implementation, not for other users): a 4-ary heap
/// ordered by (time, scheduling sequence) with cancellation by id. Cancelled entries are dropped
/// lazily when they reach the top. The order is total (no two entries share a sequence), so the
/// shape of the heap cannot change which event runs next; four children a node halve the depth a
/// removal sifts through. A heap entry is a run of events at one instant with consecutive sequences
/// (periodic timers re-armed one after another, as the drives' control periods are): nothing
/// scheduled later can come between them, so when the first has run the next takes its place at the
/// top without a sift, and the run costs the heap one push and one pop. The entries live in a
/// vector whose slots are reused; an id is the slot and the slot's generation, so that an old id
/// never names the slot's next timer (a simulated bus schedules two events per frame: no hash table
/// and no allocation per event). A header of its own, held by value in the loop: the loop asks it
/// before each event, the virtual bus at each instant of a frame (EventLoop::advance_to()), and
/// those questions, the arming of an alarm and a cancellation are inline.
class TimerQueue {
public:
    using Callback = std::function<void()>;

    struct Due {
        TimerId id;
        TimePoint when;
    };

    TimerId schedule(TimePoint when, Duration period, Callback fn);
    bool cancel(TimerId id) {
        const Entry* entry = live(id.value);
        if (entry == nullptr || entry->alarm) {
            return false;
        }
        release(id.value);
        return true;
    }
    bool pending(TimerId id) const { return live(id.value) != nullptr; }
    std::size_t size() const { return live_count_; }

    /// An alarm: a callback kept in its slot, run once each time it is armed. Arming replaces a
    /// pending time (the heap entry of the time before is dropped when it reaches the top); the
    /// order among events is that of schedule(), by (time, sequence of the arming).
    TimerId add_alarm(Callback fn);
    void arm(TimerId alarm, TimePoint when) {
        Entry& entry = entries_[slot_of(alarm.value)];
        if (!entry.live) {
            entry.live = true;
            ++live_count_;
        }
        push(when, slot_of(alarm.value));
    }
    void disarm(TimerId alarm) {
        Entry& entry = entries_[slot_of(alarm.value)];
        entry.sequence = 0;
        if (entry.live) {
            entry.live = false;
            --live_count_;
        }
    }
    void remove_alarm(TimerId alarm);

    /// The earliest live event, if any. Inline: the loop asks before each event, and the
    /// virtual bus at each instant of a frame (EventLoop::advance_to).
    std::optional<TimePoint> next_time() {
        if (!heap_.empty() && !current(heap_.front())) {
            drop_cancelled();
        }
        if (heap_.empty()) {
            return std::nullopt;
        }
        return heap_.front().when;
    }

    /// Runs the earliest live event, `now` first advanced to its time (never back). A periodic
    /// event is re-armed one period after its scheduled time unless its callback cancelled it.
    /// Precondition: next_time() has a value.
    void run_next(TimePoint& now);

private:
    static constexpr std::uint32_t kNoLink = ~std::uint32_t{0};
    /// A heap entry: the first event of a run at `when` (its sequence and entry) and the run.
    struct Slot {
        TimePoint when;
        std::uint64_t sequence;
        std::uint32_t entry;
        std::uint32_t link; // in links_: this event, followed by the rest of its run
        bool operator>(const Slot& other) const {
            return when != other.when ? when > other.when : sequence > other.sequence;
        }
    };
    /// One event of a run: the sequence it was pushed with, its entry, the next of the run.
    struct Link {
        std::uint64_t sequence;
        std::uint32_t entry;
        std::uint32_t next;
    };
    struct Entry {
        Duration period;              // zero for one-shot timers
        std::uint64_t generation = 0; // the id's high bits while the slot is in use
        /// Of its latest push while pending, else 0 (sequences start at 1): a queued event whose
        /// sequence is not its entry's is stale (cancelled, or armed again since).
        std::uint64_t sequence = 0;
        bool live = false;                // pending
        bool alarm = false;               // kept in its slot while not pending
        bool running = false;             // its callback is on the stack
        bool freed_while_running = false; // free the slot once the callback returned
    };
    static constexpr int kSlotBits = 24; // the id's low bits: 1 + the slot's index

    static std::size_t slot_of(std::uint64_t id) {
        return (id & ((std::uint64_t{1} << kSlotBits) - 1)) - 1;
    }
    /// The entry of a pending timer, or null: `id` has run, was cancelled or names nothing.
    const Entry* live(std::uint64_t id) const {
        const std::uint64_t slot = slot_of(id);
        if (slot >= entries_.size()) {
            return nullptr;
        }
        const Entry& entry = entries_[slot];
        return entry.live && entry.generation == id >> kSlotBits ? &entry : nullptr;
    }
    /// Whether the heap entry is the pending time of a live timer.
    bool current(const Slot& slot) const { return entries_[slot.entry].sequence == slot.sequence; }
    std::size_t allocate();
    void release(std::uint64_t id);
    void free_slot(std::size_t slot);
    void push(TimePoint when, std::size_t entry);
    // Inline: each event takes a link when pushed and gives it back when popped.
    std::uint32_t new_link(std::uint64_t sequence, std::size_t entry) {
        const Link link{sequence, static_cast<std::uint32_t>(entry), kNoLink};
        if (free_link_ == kNoLink) {
            links_.push_back(link);
            return static_cast<std::uint32_t>(links_.size() - 1);
        }
        const std::uint32_t index = free_link_;
        free_link_ = links_[index].next;
        links_[index] = link;
        return index;
    }
    /// Removes the top event: the next of its run takes its place, or the heap shrinks.
    void pop() {
        Slot& top = heap_.front();
        const std::uint32_t link = top.link;
        const std::uint32_t next = links_[link].next;
        links_[link].next = free_link_;
        free_link_ = link;
        if (link == tail_) {
            tail_ = kNoLink;
        }
        if (next == kNoLink) {
            pop_heap();
            return;
        }
        // The run's next event follows the top directly in (time, sequence): still the least.
        top.sequence = links_[next].sequence;
        top.entry = links_[next].entry;
        top.link = next;
    }
    void pop_heap();
    void drop_cancelled();

    std::vector<Slot> heap_; ///< heap_[0] is the earliest; the children of i are 4i+1..4i+4
    std::vector<Link> links_;
    std::uint32_t free_link_ = kNoLink; ///< the free links, chained through their `next`
    /// The link of the latest push while it is queued, and its time: a push at that time (the
    /// next sequence) joins its run.
    std::uint32_t tail_ = kNoLink;
    TimePoint tail_when_{};
    std::vector<Entry> entries_;
    /// The callback of each entry, apart: a deque does not move its elements as it grows, so a
    /// callback runs in place while it schedules more timers.
    std::deque<Callback> callbacks_;
    std::vector<std::size_t> free_slots_;
    std::size_t live_count_ = 0;
    std::uint64_t next_sequence_ = 1;
};

} // namespace eposp::core
