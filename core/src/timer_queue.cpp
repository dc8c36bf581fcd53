#include "timer_queue.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <utility>

namespace eposp::core {

std::size_t TimerQueue::allocate() {
    if (free_slots_.empty()) {
        if (entries_.size() + 1 >= (std::size_t{1} << kSlotBits)) {
            throw std::length_error("EventLoop: too many pending timers");
        }
        entries_.emplace_back();
        return entries_.size() - 1;
    }
    const std::size_t slot = free_slots_.back();
    free_slots_.pop_back();
    return slot;
}

TimerId TimerQueue::schedule(TimePoint when, Duration period, EventLoop::Callback fn) {
    const std::size_t slot = allocate();
    Entry& entry = entries_[slot];
    entry.fn = std::move(fn);
    entry.period = period;
    entry.live = true;
    ++live_count_;
    const std::uint64_t id = entry.generation << kSlotBits | (slot + 1);
    push(when, id);
    return TimerId{id};
}

TimerId TimerQueue::add_alarm(EventLoop::Callback fn) {
    const std::size_t slot = allocate();
    Entry& entry = entries_[slot];
    entry.fn = std::move(fn);
    entry.period = Duration::zero();
    entry.alarm = true;
    return TimerId{entry.generation << kSlotBits | (slot + 1)};
}

void TimerQueue::arm(TimerId alarm, TimePoint when) {
    Entry& entry = entries_[slot_of(alarm.value)];
    if (!entry.live) {
        entry.live = true;
        ++live_count_;
    }
    push(when, alarm.value);
}

void TimerQueue::disarm(TimerId alarm) {
    Entry& entry = entries_[slot_of(alarm.value)];
    if (entry.live) {
        entry.live = false;
        --live_count_;
    }
}

void TimerQueue::remove_alarm(TimerId alarm) {
    disarm(alarm);
    Entry& entry = entries_[slot_of(alarm.value)];
    entry.fn = nullptr;
    entry.alarm = false;
    ++entry.generation;
    free_slots_.push_back(slot_of(alarm.value));
}

const TimerQueue::Entry* TimerQueue::live(std::uint64_t id) const {
    const std::uint64_t slot = slot_of(id);
    if (slot >= entries_.size()) {
        return nullptr;
    }
    const Entry& entry = entries_[slot];
    return entry.live && entry.generation == id >> kSlotBits ? &entry : nullptr;
}

TimerQueue::Entry* TimerQueue::live(std::uint64_t id) {
    return const_cast<Entry*>(std::as_const(*this).live(id));
}

bool TimerQueue::current(const Slot& slot) const {
    const Entry* entry = live(slot.id);
    return entry != nullptr && entry->sequence == slot.sequence;
}

// The slot's next timer gets a new generation, so that this id no longer names it.
void TimerQueue::release(std::uint64_t id) {
    const std::size_t slot = slot_of(id);
    Entry& entry = entries_[slot];
    entry.fn = nullptr;
    entry.live = false;
    ++entry.generation;
    --live_count_;
    free_slots_.push_back(slot);
}

bool TimerQueue::cancel(TimerId id) {
    const Entry* entry = live(id.value);
    if (entry == nullptr || entry->alarm) {
        return false;
    }
    release(id.value);
    return true;
}

void TimerQueue::push(TimePoint when, std::uint64_t id) {
    const Slot slot{when, next_sequence_++, id};
    entries_[slot_of(id)].sequence = slot.sequence;
    std::size_t hole = heap_.size();
    heap_.push_back(slot);
    while (hole > 0) {
        const std::size_t parent = (hole - 1) / 4;
        if (!(heap_[parent] > slot)) {
            break;
        }
        heap_[hole] = heap_[parent];
        hole = parent;
    }
    heap_[hole] = slot;
}

void TimerQueue::pop() {
    const Slot last = heap_.back();
    heap_.pop_back();
    const std::size_t size = heap_.size();
    if (size == 0) {
        return;
    }
    std::size_t hole = 0;
    for (;;) {
        const std::size_t first = 4 * hole + 1;
        if (first >= size) {
            break;
        }
        std::size_t least = first;
        const std::size_t end = std::min(first + 4, size);
        for (std::size_t child = first + 1; child < end; ++child) {
            if (heap_[least] > heap_[child]) {
                least = child;
            }
        }
        if (!(last > heap_[least])) {
            break;
        }
        heap_[hole] = heap_[least];
        hole = least;
    }
    heap_[hole] = last;
}

void TimerQueue::drop_cancelled() {
    while (!heap_.empty() && !current(heap_.front())) {
        pop();
    }
}

std::optional<TimePoint> TimerQueue::next_time() {
    drop_cancelled();
    if (heap_.empty()) {
        return std::nullopt;
    }
    return heap_.front().when;
}

void TimerQueue::run_next(TimePoint& now) {
    drop_cancelled();
    assert(!heap_.empty());
    const Slot slot = heap_.front();
    pop();
    now = std::max(now, slot.when);

    // The callback is moved out while it runs so that it may cancel itself or schedule more
    // timers (which may grow the entries) without destroying the function being executed.
    EventLoop::Callback fn = std::move(entries_[slot_of(slot.id)].fn);
    if (entries_[slot_of(slot.id)].alarm) {
        // Armed while it runs, as a timer is pending until its callback returns.
        fn();
        Entry& entry = entries_[slot_of(slot.id)];
        if (entry.generation != slot.id >> kSlotBits) {
            return; // removed by its own callback
        }
        entry.fn = std::move(fn);
        if (entry.sequence == slot.sequence) {
            disarm(TimerId{slot.id}); // not armed again by its callback
        }
        return;
    }
    fn();

    Entry* entry = live(slot.id);
    if (entry == nullptr) {
        return; // cancelled by its own callback
    }
    if (entry->period == Duration::zero()) {
        release(slot.id);
        return;
    }
    entry->fn = std::move(fn);
    push(slot.when + entry->period, slot.id);
}

} // namespace eposp::core
