#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/can/trace_clock.hpp"

#include <string_view>

namespace eposp::can {

/// A trace being written: a candump log or a pcap file. Buses feed it through a recorder, so
/// every bus records the same way.
class TraceSink {
public:
    virtual ~TraceSink() = default;

    /// Records `frame` (a data, remote or error frame) as seen on `interface_name` at `time`.
    virtual void record(TraceTime time, std::string_view interface_name, const Frame& frame) = 0;
};

} // namespace eposp::can
