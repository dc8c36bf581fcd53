#pragma once

#include "eposp/service/frame.hpp"

#include <cstdint>
#include <span>

namespace eposp::service {

/// The CRC of maxon's serial protocols (maxon EPOS2 communication guide, "CRC calculation"):
/// CRC-CCITT (polynomial 0x1021, initial value 0) over 16-bit words, most significant bit first:
/// the header word `first_word`, then each data word (`data` holds them low byte first), then
/// one 0x0000 word. `data` must have an even length.
std::uint16_t frame_crc(std::uint16_t first_word, std::span<const std::uint8_t> data);

/// The CRC of a frame on the RS-232 link (v1): the header word is `OpCode << 8 | (Len - 1)`.
/// The frame holds 1 to 256 words.
std::uint16_t v1_crc(const Frame& frame);

/// The CRC of a frame on the USB link (v2), over the unstuffed frame: the header word is
/// `Len << 8 | OpCode` (the two header bytes read as one little-endian word). At most 255 words.
std::uint16_t v2_crc(const Frame& frame);

} // namespace eposp::service
