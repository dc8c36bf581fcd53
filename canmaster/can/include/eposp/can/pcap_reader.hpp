#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/can/trace_clock.hpp"
#include "eposp/core/result.hpp"

#include <bit>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <vector>

namespace eposp::can {

struct PcapHeader {
    std::uint32_t magic = 0; ///< 0xA1B2C3D4 (µs timestamps) or 0xA1B23C4D (ns timestamps)
    std::endian byte_order = std::endian::little;
    std::uint16_t version_major = 0;
    std::uint16_t version_minor = 0;
    std::uint32_t snap_length = 0;
    std::uint32_t link_type = 0;
};

struct PcapRecord {
    TraceTime time;
    std::uint32_t length = 0; ///< bytes of packet data, captured and original alike
    Frame frame;
};

struct PcapCapture {
    PcapHeader header;
    std::vector<PcapRecord> records;
};

/// Reads a whole pcap file of CAN frames and checks that it is well formed: a pcap magic (µs or
/// ns, either byte order), version 2.4, link type LINKTYPE_CAN_SOCKETCAN, a snap length above 0,
/// and records that are not truncated, fit the snap length and hold a whole classic CAN frame.
/// An error names the record (counted from 1).
core::Result<PcapCapture> read_pcap(std::istream& in);

/// As above from a file; errors name the file.
core::Result<PcapCapture> read_pcap_file(const std::filesystem::path& path);

} // namespace eposp::can
