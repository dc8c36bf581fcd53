#pragma once

#include "eposp/can/trace_output.hpp"
#include "eposp/can/trace_sink.hpp"

namespace eposp::can {

/// Writes a pcap file of LINKTYPE_CAN_SOCKETCAN (227) records with nanosecond timestamps, which
/// Wireshark and tshark read (`tshark -r FILE -d can.subdissector,canopen` decodes CANopen).
/// The file header is written at construction, so even a run without traffic leaves a valid
/// file. pcap has no interface names: a file records one bus.
class PcapWriter final : public TraceSink {
public:
    explicit PcapWriter(TraceOutput output);

    void record(TraceTime time, std::string_view interface_name, const Frame& frame) override;
    bool good() const { return output_.good(); }

private:
    TraceOutput output_;
};

} // namespace eposp::can
