#include "eposp/core/timer_queue.hpp"

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
        callbacks_.emplace_back();
        return entries_.size() - 1;
    }
    const std::size_t slot = free_slots_.back();
    free_slots_.pop_back();
    return slot;
}

TimerId TimerQueue::schedule(TimePoint when, Duration period, Callback fn) {
    const std::size_t slot = allocate();
    Entry& entry = entries_[slot];
    callbacks_[slot] = std::move(fn);
    entry.period = period;
    entry.live = true;
    ++live_count_;
    push(when, slot);
    return TimerId{entry.generation << kSlotBits | (slot + 1)};
}

TimerId TimerQueue::add_alarm(Callback fn) {
    const std::size_t slot = allocate();
    Entry& entry = entries_[slot];
    callbacks_[slot] = std::move(fn);
    entry.period = Duration::zero();
    entry.alarm = true;
    return TimerId{entry.generation << kSlotBits | (slot + 1)};
}

void TimerQueue::remove_alarm(TimerId alarm) {
    disarm(alarm);
    Entry& entry = entries_[slot_of(alarm.value)];
    entry.alarm = false;
    ++entry.generation;
    free_slot(slot_of(alarm.value));
}

// A callback that is running is destroyed, and its slot reused, once it has returned.
void TimerQueue::free_slot(std::size_t slot) {
    if (entries_[slot].running) {
        entries_[slot].freed_while_running = true;
        return;
    }
    callbacks_[slot] = nullptr;
    free_slots_.push_back(slot);
}

// The slot's next timer gets a new generation, so that this id no longer names it.
void TimerQueue::release(std::uint64_t id) {
    const std::size_t slot = slot_of(id);
    Entry& entry = entries_[slot];
    entry.live = false;
    entry.sequence = 0;
    ++entry.generation;
    --live_count_;
    free_slot(slot);
}

void TimerQueue::push(TimePoint when, std::size_t entry) {
    const std::uint64_t sequence = next_sequence_++;
    entries_[entry].sequence = sequence;
    const std::uint32_t link = new_link(sequence, entry);
    // The latest push, still queued, has the sequence before this one: at the same time, nothing
    // can come between the two, so this event joins its run.
    if (tail_ != kNoLink && tail_when_ == when) {
        links_[tail_].next = link;
        tail_ = link;
        return;
    }
    tail_ = link;
    tail_when_ = when;
    const Slot slot{when, sequence, static_cast<std::uint32_t>(entry), link};
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

void TimerQueue::pop_heap() {
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

void TimerQueue::run_next(TimePoint& now) {
    assert(!heap_.empty());
    if (!current(heap_.front())) { // the caller asked next_time() just before: mostly current
        drop_cancelled();
    }
    const Slot slot = heap_.front();
    pop();
    now = std::max(now, slot.when);

    // The callback runs in place: callbacks_ keeps its elements where they are while the callback
    // schedules more timers, and a callback that cancels or removes itself is destroyed only
    // once it has returned (free_slot).
    const std::uint64_t id = entries_[slot.entry].generation << kSlotBits | (slot.entry + 1);
    const bool nested = std::exchange(entries_[slot.entry].running, true);
    try {
        callbacks_[slot.entry]();
    } catch (...) {
        entries_[slot.entry].running = nested; // a programming error: the caller sees it
        throw;
    }
    Entry& entry = entries_[slot.entry];
    entry.running = nested;
    if (entry.freed_while_running && !nested) {
        entry.freed_while_running = false;
        free_slot(slot.entry);
        return; // cancelled or removed by its own callback
    }
    if (entry.generation != id >> kSlotBits || !entry.live) {
        return; // cancelled or removed by its own callback
    }
    if (entry.alarm) {
        // Armed while it runs, as a timer is pending until its callback returns.
        if (entry.sequence == slot.sequence) {
            disarm(TimerId{id}); // not armed again by its callback
        }
        return;
    }
    if (entry.period == Duration::zero()) {
        release(id);
        return;
    }
    push(slot.when + entry.period, slot.entry);
}

} // namespace eposp::core
