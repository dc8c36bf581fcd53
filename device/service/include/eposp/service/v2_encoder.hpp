#pragma once

#include "eposp/service/frame.hpp"

#include <cstdint>
#include <vector>

namespace eposp::service {

/// The two bytes that start every frame on the USB link (v2): DLE, STX.
inline constexpr std::uint8_t kV2Dle = 0x90;
inline constexpr std::uint8_t kV2Stx = 0x02;

/// A frame as the USB link (v2) sends it, both ways (maxon EPOS2 communication guide, "USB
/// protocol"): 0x90 0x02, then OpCode, Len (data words), the data, the CRC low byte first, with
/// every 0x90 after the start doubled (byte stuffing). Throws std::invalid_argument for a frame
/// of more than 255 words or of an odd data length.
std::vector<std::uint8_t> encode_v2(const Frame& frame);

} // namespace eposp::service
