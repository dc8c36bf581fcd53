#pragma once

#include "eposp/core/time.hpp"
#include "eposp/core/timer_queue.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

namespace boost::asio {
class io_context;
}

namespace eposp::core {

/// How the loop's clock advances (docs/architecture.md, "One clock, two speeds").
enum class Pace {
    Virtual,  ///< jump from event to event as fast as the CPU allows; deterministic
    RealTime, ///< follow the wall clock and wait on file descriptors while no event is due
};

/// The one discrete-event loop that everything with time is scheduled on: task cycles, SYNC,
/// heartbeats, bus frame times, drive control loops. Events at the same instant run in the
/// order they were scheduled, so a virtual run is bit-for-bit repeatable.
///
/// Single-threaded: every member is called from the thread that runs the loop, except stop().
class EventLoop {
public:
    using Callback = TimerQueue::Callback;

    explicit EventLoop(Pace pace = Pace::Virtual);
    ~EventLoop();
    EventLoop(const EventLoop&) = delete;
    EventLoop& operator=(const EventLoop&) = delete;

    Pace pace() const { return pace_; }
    TimePoint now() const {
        // In real time, code outside a timer callback (an I/O handler, the caller before run())
        // sees the wall clock; a timer callback sees its scheduled time unless something
        // already saw a later wall time: the clock never goes backwards.
        if (pace_ == Pace::RealTime && !dispatching_) {
            return catch_up_with_wall_clock();
        }
        return now_;
    }

    /// Runs `fn` at `when`; a time in the past means "now, after what is already due".
    TimerId at(TimePoint when, Callback fn);
    TimerId after(Duration delay, Callback fn);
    /// Runs `fn` at `first`, `first + period`, `first + 2*period`, ... The times are computed
    /// from the schedule, not from when the callback ran, so the timer never drifts.
    TimerId every(Duration period, TimePoint first, Callback fn);
    /// As above with the first run one period from now.
    TimerId every(Duration period, Callback fn);
    /// Runs `fn` now, after the events already due (a deferred call).
    TimerId post(Callback fn) { return after(Duration::zero(), std::move(fn)); }
    /// From a callback: whether a call post()ed now would run right after it, with nothing in
    /// between (virtual pace, no other event due now, no I/O to poll, no stop() pending). The
    /// callback may then make the call itself and save an event (the virtual bus arbitrates so).
    bool next_in_line() {
        if (!may_run_on()) {
            return false;
        }
        const std::optional<TimePoint> next = timers_.next_time();
        return !next || *next > now_;
    }
    /// From a callback: whether an event armed now for `when` would be the next to run (virtual
    /// pace, no I/O to poll, no stop() pending, no other event due by `when`, `when` within the
    /// running run_until()). If so the clock moves to `when` and the callback goes on as that
    /// event would, counted as one callback run: nothing else can act in between, so nothing
    /// can tell the difference (the virtual bus carries a frame to its end and on so).
    /// Inline, as the questions below: the bus asks at each instant of every frame.
    bool advance_to(TimePoint when) {
        if (!dispatching_ || when > run_end_ || !may_run_on()) {
            return false;
        }
        const std::optional<TimePoint> next = timers_.next_time();
        if (next && *next <= when) {
            return false;
        }
        now_ = std::max(now_, when);
        ++dispatched_;
        return true;
    }

    /// Cancels a pending timer; safe from within its own callback. Returns false when the timer
    /// already ran (one-shot) or was cancelled before.
    bool cancel(TimerId id) { return timers_.cancel(id); }
    bool pending(TimerId id) const { return timers_.pending(id); }
    /// Number of timers scheduled and not cancelled.
    std::size_t pending_count() const { return timers_.size(); }

    /// Runs events until `end` (inclusive) or stop(); afterwards now() == end unless stopped.
    /// Returns the number of timer callbacks run.
    std::uint64_t run_until(TimePoint end);
    std::uint64_t run_for(Duration d) { return run_until(now() + d); }
    /// Virtual pace: until no event is left. Real-time pace: until stop().
    std::uint64_t run();

    /// Makes the running run_*() return after the current callback. Thread-safe, so a signal
    /// watcher or another thread may call it.
    void stop();
    bool stop_requested() const { return stop_requested_.load(); }

    /// The Boost.Asio context that components waiting on file descriptors (sockets, serial
    /// ports, SocketCAN) use. Its handlers run inside run_*(), interleaved with timer events:
    /// in real-time pace the loop blocks in it while no event is due, in virtual pace it is
    /// polled between events.
    boost::asio::io_context& io();

private:
    friend class Alarm;
    TimerId add_alarm(Callback fn) { return timers_.add_alarm(std::move(fn)); }
    void arm(TimerId alarm, TimePoint when) { timers_.arm(alarm, std::max(when, now())); }
    void disarm(TimerId alarm) { timers_.disarm(alarm); }
    void remove_alarm(TimerId alarm) { timers_.remove_alarm(alarm); }

    /// Virtual pace with no I/O to poll and no stop() pending: a callback may go on with what
    /// the loop would run next (next_in_line(), advance_to()).
    bool may_run_on() const { return pace_ == Pace::Virtual && !io_ && !stop_requested_; }
    /// now() in real time outside a timer callback.
    TimePoint catch_up_with_wall_clock() const;
    void dispatch_next();
    void run_virtual(TimePoint end);
    void run_real_time(TimePoint end);
    TimePoint wall_now() const;

    Pace pace_;
    mutable TimePoint now_{};
    bool dispatching_ = false;
    TimePoint run_end_{}; ///< the running run_until()'s end
    std::atomic<bool> stop_requested_{false};
    std::uint64_t dispatched_ = 0;
    TimerQueue timers_;
    std::unique_ptr<boost::asio::io_context> io_;
    std::chrono::steady_clock::time_point wall_origin_;
};

/// Owns a timer and cancels it when destroyed, so that a callback never outlives its object.
class ScopedTimer {
public:
    ScopedTimer() = default;
    ScopedTimer(EventLoop& loop, TimerId id) : loop_(&loop), id_(id) {}
    ScopedTimer(ScopedTimer&& other) noexcept
        : loop_(std::exchange(other.loop_, nullptr)), id_(std::exchange(other.id_, TimerId{})) {}
    ScopedTimer& operator=(ScopedTimer&& other) noexcept {
        if (this != &other) {
            cancel();
            loop_ = std::exchange(other.loop_, nullptr);
            id_ = std::exchange(other.id_, TimerId{});
        }
        return *this;
    }
    ~ScopedTimer() { cancel(); }

    /// Inline: an empty timer (most of them, most of the time) costs a test.
    void cancel() {
        if (loop_ && id_) {
            loop_->cancel(id_);
        }
        id_ = TimerId{};
    }
    bool pending() const { return loop_ && loop_->pending(id_); }
    TimerId id() const { return id_; }

private:
    EventLoop* loop_ = nullptr;
    TimerId id_{};
};

/// One callback, fixed once, that runs each time it is armed: for an object whose events come
/// one after another (the virtual bus's end of frame and end of intermission), without a new
/// timer and its callback per event. Arming at a time is scheduling with at(): it runs in the
/// same order among the other events; arming again while armed moves it to the new time.
class Alarm {
public:
    Alarm(EventLoop& loop, EventLoop::Callback fn)
        : loop_(loop), id_(loop.add_alarm(std::move(fn))) {}
    ~Alarm() { loop_.remove_alarm(id_); }
    Alarm(const Alarm&) = delete;
    Alarm& operator=(const Alarm&) = delete;

    /// Runs the callback at `when` (a time in the past: now, after what is already due).
    void arm(TimePoint when) { loop_.arm(id_, when); }
    void disarm() { loop_.disarm(id_); }
    /// Armed from arm() until its callback returned (unless that armed it again) or disarm().
    bool armed() const { return loop_.pending(id_); }

private:
    EventLoop& loop_;
    TimerId id_;
};

} // namespace eposp::core
