#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/core/result.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

// Internal: the classic pcap file format (draft-ietf-opsawg-pcap) with LINKTYPE_CAN_SOCKETCAN
// records (https://www.tcpdump.org/linktypes/LINKTYPE_CAN_SOCKETCAN.html), shared by the writer
// and the reader.
namespace eposp::can::pcap {

inline constexpr std::uint32_t kMicrosecondMagic = 0xA1B2'C3D4;
inline constexpr std::uint32_t kNanosecondMagic = 0xA1B2'3C4D;
inline constexpr std::uint16_t kVersionMajor = 2;
inline constexpr std::uint16_t kVersionMinor = 4;
inline constexpr std::uint32_t kLinkTypeCanSocketCan = 227;
inline constexpr std::uint32_t kSnapLength = 65535;
inline constexpr std::size_t kFileHeaderSize = 24;
inline constexpr std::size_t kRecordHeaderSize = 16;
/// can_id (4, big-endian), payload length, FD flags, 2 reserved bytes.
inline constexpr std::size_t kCanHeaderSize = 8;
/// The header and 8 data bytes: SocketCAN's CAN_MTU.
inline constexpr std::size_t kCanFrameSize = kCanHeaderSize + kMaxDataLength;

using CanFrameBytes = std::array<std::uint8_t, kCanFrameSize>;

CanFrameBytes encode_can_frame(const Frame& frame);
/// Reads a frame from a record's packet data; `bytes` may be longer than the frame needs.
core::Result<Frame> decode_can_frame(std::span<const std::uint8_t> bytes);

} // namespace eposp::can::pcap
