#include "interruptible_run.hpp"

#include <algorithm>
#include <csignal>

namespace eposp::device::cli {
namespace {

// Only a signal handler writes it (POSIX: volatile sig_atomic_t is what a handler may set).
volatile std::sig_atomic_t signal_arrived = 0;

extern "C" void note_signal(int) {
    signal_arrived = 1;
}

// Catches SIGINT and SIGTERM while it lives; restores the previous actions after.
class CaughtSignals {
public:
    CaughtSignals() {
        signal_arrived = 0;
        struct sigaction action {};
        action.sa_handler = note_signal;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &previous_interrupt_);
        sigaction(SIGTERM, &action, &previous_terminate_);
    }
    ~CaughtSignals() {
        sigaction(SIGINT, &previous_interrupt_, nullptr);
        sigaction(SIGTERM, &previous_terminate_, nullptr);
    }
    CaughtSignals(const CaughtSignals&) = delete;
    CaughtSignals& operator=(const CaughtSignals&) = delete;

private:
    struct sigaction previous_interrupt_ {};
    struct sigaction previous_terminate_ {};
};

} // namespace

bool run_until_interrupted(core::EventLoop& loop, core::TimePoint end, core::Duration slice) {
    const CaughtSignals caught;
    // At least one slice: events due now run even when `end` is now.
    do {
        if (signal_arrived != 0) {
            return true;
        }
        const core::TimePoint until = std::min(end, loop.now() + slice);
        loop.run_until(until);
        if (loop.now() < until) {
            return false; // stopped from inside (EventLoop::stop)
        }
    } while (loop.now() < end);
    return false;
}

} // namespace eposp::device::cli
