#include "eposp/device/run_control.hpp"

#include <boost/asio/signal_set.hpp>
#include <csignal>

namespace eposp::device {

RunEnd run_until_done(core::EventLoop& loop, std::optional<core::Duration> duration) {
    bool interrupted = false;
    boost::asio::signal_set signals(loop.io(), SIGINT, SIGTERM);
    signals.async_wait([&](const boost::system::error_code& error, int) {
        if (!error) {
            interrupted = true;
            loop.stop();
        }
    });
    if (duration) {
        loop.run_for(*duration);
    } else {
        loop.run();
    }
    signals.cancel();
    loop.io().poll(); // completes the cancelled wait while `signals` still exists
    if (interrupted) {
        return RunEnd::Interrupted;
    }
    return duration ? RunEnd::Elapsed : RunEnd::Idle;
}

} // namespace eposp::device
