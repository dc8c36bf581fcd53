#include "timer_queue.hpp"

#include <cassert>

namespace eposp::core {

TimerId TimerQueue::schedule(TimePoint when, Duration period, EventLoop::Callback fn) {
    const std::uint64_t id = next_id_++;
    entries_.emplace(id, Entry{std::move(fn), period});
    push(when, id);
    return TimerId{id};
}

bool TimerQueue::cancel(TimerId id) {
    return entries_.erase(id.value) > 0;
}

void TimerQueue::push(TimePoint when, std::uint64_t id) {
    heap_.push(Slot{when, next_sequence_++, id});
}

void TimerQueue::drop_cancelled() {
    while (!heap_.empty() && !entries_.contains(heap_.top().id)) {
        heap_.pop();
    }
}

std::optional<TimePoint> TimerQueue::next_time() {
    drop_cancelled();
    if (heap_.empty()) {
        return std::nullopt;
    }
    return heap_.top().when;
}

void TimerQueue::run_next(const std::function<void(TimePoint)>& set_now) {
    drop_cancelled();
    assert(!heap_.empty());
    const Slot slot = heap_.top();
    heap_.pop();
    set_now(slot.when);

    // The callback is moved out while it runs so that it may cancel itself or schedule more
    // timers (which may rehash the map) without destroying the function being executed.
    auto it = entries_.find(slot.id);
    EventLoop::Callback fn = std::move(it->second.fn);
    fn();

    it = entries_.find(slot.id);
    if (it == entries_.end()) {
        return; // cancelled by its own callback
    }
    if (it->second.period == Duration::zero()) {
        entries_.erase(it);
        return;
    }
    it->second.fn = std::move(fn);
    push(slot.when + it->second.period, slot.id);
}

} // namespace eposp::core
