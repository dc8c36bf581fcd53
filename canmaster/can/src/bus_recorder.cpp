#include "eposp/can/bus_recorder.hpp"

namespace eposp::can {

BusRecorder::BusRecorder(VirtualBus& bus, TraceSink& sink, TraceClock clock)
    : bus_(bus),
      observer_(bus.add_observer([&sink, clock, name = bus.config().name](const WireEvent& event) {
          sink.record(clock.to_trace(event.end), name, event.frame);
      })) {}

BusRecorder::~BusRecorder() {
    bus_.remove_observer(observer_);
}

} // namespace eposp::can
