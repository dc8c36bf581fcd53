#pragma once

// For the tests of the byte links: a loop driven until something has happened, a host that
// opens a serial device with plain POSIX calls, and a link that records what is sent on it.

#include "eposp/core/event_loop.hpp"
#include "eposp/service/link.hpp"

#include <cerrno>
#include <chrono>
#include <fcntl.h>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

namespace eposp::service::test {

using namespace std::chrono_literals;

/// Runs the loop until `done()` holds, 5 s at most (a real-time loop waits on its file
/// descriptors meanwhile; nothing sleeps); whether it holds.
inline bool run_until(core::EventLoop& loop, const std::function<bool()>& done,
                      core::Duration deadline = 5s) {
    if (done()) {
        return true;
    }
    core::ScopedTimer check(loop, loop.every(1ms, [&] {
        if (done()) {
            loop.stop();
        }
    }));
    loop.run_for(deadline);
    return done();
}

inline std::span<const std::uint8_t> bytes_of(std::string_view text) {
    return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

/// A program on the other end of a serial device: open(), write(), read(), close().
class PosixHost {
public:
    explicit PosixHost(const std::string& path)
        : fd_(::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC)) {}
    ~PosixHost() { close(); }
    PosixHost(const PosixHost&) = delete;
    PosixHost& operator=(const PosixHost&) = delete;

    bool is_open() const { return fd_ >= 0; }
    bool write(std::string_view text) {
        return ::write(fd_, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    }
    /// Reads what is there now; false once the device side is gone (EIO or end of file).
    bool read_available() {
        char buffer[4096];
        for (;;) {
            const ssize_t n = ::read(fd_, buffer, sizeof buffer);
            if (n > 0) {
                received_.append(buffer, static_cast<std::size_t>(n));
                continue;
            }
            return n < 0 && errno == EAGAIN;
        }
    }
    const std::string& received() const { return received_; }
    void close() {
        if (fd_ >= 0) {
            ::close(fd_);
            fd_ = -1;
        }
    }

private:
    int fd_;
    std::string received_;
};

/// Collects what a link receives and reports.
struct LinkRecorder {
    explicit LinkRecorder(Link& link) {
        link.on_receive([this](std::span<const std::uint8_t> bytes) {
            received.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        });
        link.on_event([this](const LinkEvent& event) { events.push_back(event); });
    }
    std::size_t count(LinkEvent::Kind kind) const {
        std::size_t n = 0;
        for (const LinkEvent& event : events) {
            n += event.kind == kind ? 1 : 0;
        }
        return n;
    }

    std::string received;
    std::vector<LinkEvent> events;
};

} // namespace eposp::service::test
