#pragma once

#include "eposp/can/candump_format.hpp"
#include "eposp/can/port.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace eposp::can {

struct ReplayReport {
    std::uint64_t sent = 0;    ///< accepted by the port
    std::uint64_t refused = 0; ///< refused by the port: queue full, bus-off, disconnected, ...
    /// Not played: logged on another interface, or error frames, which are bus events that no
    /// port can send.
    std::uint64_t skipped = 0;
};

struct ReplayOptions {
    /// When the first frame is sent; now when not given.
    std::optional<core::TimePoint> start{};
    /// Plays only the frames logged on this interface; all frames when empty.
    std::string interface_name{};
    /// Called once, from the loop, after the last frame was handed to the port.
    std::function<void(const ReplayReport&)> on_finished{};
};

/// Plays a candump log onto a bus through a port, like canplayer: each frame is sent at the
/// start time plus its log time relative to the first frame played, so the log's timing is kept
/// on the event loop. Destroying the replay stops it.
class CandumpReplay {
public:
    CandumpReplay(core::EventLoop& loop, Port& port, std::vector<CandumpRecord> records,
                  ReplayOptions options = {});
    CandumpReplay(const CandumpReplay&) = delete;
    CandumpReplay& operator=(const CandumpReplay&) = delete;

    const ReplayReport& report() const { return report_; }
    bool finished() const { return finished_; }

private:
    bool plays(const CandumpRecord& record) const;
    void schedule_next();
    void send_next();
    void finish();

    core::EventLoop& loop_;
    Port& port_;
    std::vector<CandumpRecord> records_;
    ReplayOptions options_;
    core::TimePoint start_;
    std::optional<TraceTime> first_time_;
    std::size_t next_ = 0;
    ReplayReport report_;
    bool finished_ = false;
    core::ScopedTimer timer_;
};

} // namespace eposp::can
