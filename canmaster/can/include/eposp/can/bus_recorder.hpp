#pragma once

#include "eposp/can/trace_clock.hpp"
#include "eposp/can/trace_sink.hpp"
#include "eposp/can/virtual_bus.hpp"

namespace eposp::can {

/// Records everything a VirtualBus carries, frames and error frames, into a trace until it is
/// destroyed. Frames are timestamped at their end, when receivers have them, under the bus's
/// interface name. The bus and the sink must outlive the recorder.
class BusRecorder {
public:
    BusRecorder(VirtualBus& bus, TraceSink& sink, TraceClock clock = {});
    ~BusRecorder();
    BusRecorder(const BusRecorder&) = delete;
    BusRecorder& operator=(const BusRecorder&) = delete;

private:
    VirtualBus& bus_;
    VirtualBus::ObserverId observer_;
};

} // namespace eposp::can
