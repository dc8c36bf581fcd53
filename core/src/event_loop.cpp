#include "eposp/core/event_loop.hpp"

#include <algorithm>
#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <stdexcept>
#include <utility>

namespace eposp::core {
namespace {

/// Sets a variable for a scope and gives it its value back when the scope ends, by a return or
/// by an exception.
template <typename T>
class Restore {
public:
    Restore(T& variable, T value) : variable_(variable), saved_(std::exchange(variable, value)) {}
    ~Restore() { variable_ = saved_; }
    Restore(const Restore&) = delete;
    Restore& operator=(const Restore&) = delete;

private:
    T& variable_;
    T saved_;
};

} // namespace

EventLoop::EventLoop(Pace pace) : pace_(pace), wall_origin_(std::chrono::steady_clock::now()) {}

EventLoop::~EventLoop() = default;

TimePoint EventLoop::wall_now() const {
    return TimePoint{
        std::chrono::duration_cast<Duration>(std::chrono::steady_clock::now() - wall_origin_)};
}

TimePoint EventLoop::catch_up_with_wall_clock() const {
    now_ = std::max(now_, wall_now());
    return now_;
}

TimerId EventLoop::at(TimePoint when, Callback fn) {
    return timers_.schedule(std::max(when, now()), Duration::zero(), std::move(fn));
}

TimerId EventLoop::after(Duration delay, Callback fn) {
    return at(now() + delay, std::move(fn));
}

TimerId EventLoop::every(Duration period, TimePoint first, Callback fn) {
    if (period <= Duration::zero()) {
        throw std::invalid_argument("EventLoop::every: the period must be positive");
    }
    return timers_.schedule(std::max(first, now()), period, std::move(fn));
}

TimerId EventLoop::every(Duration period, Callback fn) {
    return every(period, now() + period, std::move(fn));
}

boost::asio::io_context& EventLoop::io() {
    if (!io_) {
        io_ = std::make_unique<boost::asio::io_context>(1);
    }
    return *io_;
}

void EventLoop::stop() {
    stop_requested_ = true;
    if (io_) {
        boost::asio::post(*io_, [] {}); // wakes a real-time loop blocked in the io_context
    }
}

void EventLoop::dispatch_next() {
    {
        // An inner run (a callback that runs the loop) leaves its callback dispatching.
        const Restore<bool> dispatching(dispatching_, true);
        timers_.run_next(now_);
    }
    ++dispatched_;
}

std::uint64_t EventLoop::run_until(TimePoint end) {
    stop_requested_ = false;
    const std::uint64_t before = dispatched_;
    // A callback may run the loop itself: its run's end holds again when that returns, also
    // when a callback's exception leaves the inner run.
    const Restore<TimePoint> run_end(run_end_, end);
    if (pace_ == Pace::Virtual) {
        run_virtual(end);
    } else {
        run_real_time(end);
    }
    return dispatched_ - before;
}

std::uint64_t EventLoop::run() {
    return run_until(TimePoint::max());
}

void EventLoop::run_virtual(TimePoint end) {
    while (!stop_requested_) {
        if (io_) {
            io_->poll();
        }
        const auto next = timers_.next_time();
        if (!next || *next > end) {
            if (end != TimePoint::max()) {
                now_ = std::max(now_, end);
            }
            return;
        }
        dispatch_next();
    }
}

void EventLoop::run_real_time(TimePoint end) {
    auto& context = io();
    auto work = boost::asio::make_work_guard(context);
    context.restart();
    while (!stop_requested_) {
        context.poll();
        if (stop_requested_) {
            return;
        }
        const auto next = timers_.next_time();
        const TimePoint target = next ? std::min(*next, end) : end;
        if (target > wall_now()) {
            // Block on file descriptors until the target time; an I/O handler may schedule an
            // earlier event, so the target is computed again after every handler.
            const auto wall_deadline =
                target == TimePoint::max()
                    ? std::chrono::steady_clock::time_point::max()
                    : wall_origin_ +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              target.time_since_epoch());
            context.run_one_until(wall_deadline);
            continue;
        }
        if (next && *next <= end) {
            dispatch_next();
        } else {
            return; // reached `end`
        }
    }
}

} // namespace eposp::core
