#pragma once

#include "eposp/can/trace_output.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"
#include "eposp/plcopen/axis_driver.hpp"

#include <cstdint>
#include <string_view>
#include <vector>

namespace eposp::device {

/// An axis served by a drive simulated in this process.
struct TracedAxis {
    std::uint8_t axis = 0;
    const drives::epos2::Epos2Drive* drive = nullptr;
    /// How the motion blocks see the axis: its PLCopen state.
    const plcopen::AxisDriver* driver = nullptr;
};

/// A CSV trace of simulated axes, as an oscilloscope on the drives would take it: every
/// `period` one row per axis with the drive's own values (its objects, not what reached the
/// EPOS P), and the axis' PLCopen state as the motion blocks see it. Times are seconds of loop
/// time, values integers in the drive's units (quadcounts, rpm, mA), so a plotting tool reads the
/// file directly and two runs of the same network give the same bytes.
class AxisTrace {
public:
    static constexpr std::string_view kHeader =
        "time_s,axis,statusword,mode,target_position,position_demand,actual_position,"
        "velocity_demand,actual_velocity,current_mA,plcopen_state\n";

    /// Writes the header, then a row per axis at each period from now on; the axes' drives
    /// must outlive the trace.
    AxisTrace(core::EventLoop& loop, can::TraceOutput output, std::vector<TracedAxis> axes,
              core::Duration period);
    AxisTrace(const AxisTrace&) = delete;
    AxisTrace& operator=(const AxisTrace&) = delete;

    /// False once a write failed.
    bool good() const { return output_.good(); }

private:
    void sample();

    core::EventLoop& loop_;
    can::TraceOutput output_;
    std::vector<TracedAxis> axes_;
    core::ScopedTimer timer_;
};

} // namespace eposp::device
