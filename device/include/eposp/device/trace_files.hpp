#pragma once

#include "eposp/can/bus_recorder.hpp"
#include "eposp/can/trace_clock.hpp"
#include "eposp/can/trace_output.hpp"
#include "eposp/can/trace_sink.hpp"
#include "eposp/can/virtual_bus.hpp"

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eposp::device {

/// The CAN traces a command writes (candump -L logs, pcap files): each records the buses it was
/// given, under their interface names, until this is destroyed.
class TraceFiles {
public:
    explicit TraceFiles(can::TraceClock clock = {}) : clock_(clock) {}

    /// Creates the trace `path` with a Writer (can::CandumpLogWriter, can::PcapWriter) and
    /// records `buses` into it; or says why the file cannot be created.
    template <typename Writer>
    std::optional<std::string> add(const std::string& path,
                                   std::initializer_list<can::VirtualBus*> buses) {
        auto output = can::TraceOutput::create(path);
        if (!output) {
            return output.error();
        }
        sinks_.push_back(std::make_unique<Writer>(std::move(*output)));
        for (can::VirtualBus* bus : buses) {
            recorders_.push_back(std::make_unique<can::BusRecorder>(*bus, *sinks_.back(), clock_));
        }
        return std::nullopt;
    }

private:
    can::TraceClock clock_;
    std::vector<std::unique_ptr<can::TraceSink>> sinks_;
    std::vector<std::unique_ptr<can::BusRecorder>> recorders_;
};

} // namespace eposp::device
