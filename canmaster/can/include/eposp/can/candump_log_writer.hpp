#pragma once

#include "eposp/can/trace_output.hpp"
#include "eposp/can/trace_sink.hpp"

namespace eposp::can {

/// Writes a `candump -L` log, one line per frame, that canplayer and log2asc read.
class CandumpLogWriter final : public TraceSink {
public:
    explicit CandumpLogWriter(TraceOutput output) : output_(std::move(output)) {}

    void record(TraceTime time, std::string_view interface_name, const Frame& frame) override;
    bool good() const { return output_.good(); }

private:
    TraceOutput output_;
};

} // namespace eposp::can
