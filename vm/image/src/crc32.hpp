#pragma once

#include <cstdint>
#include <span>

namespace eposp::vm::detail {

/// CRC-32 as zlib and boost::crc_32_type compute it (polynomial 0x04C11DB7, reflected, initial
/// value and final XOR all ones): the image file's checksum.
std::uint32_t crc32(std::span<const std::uint8_t> bytes);

} // namespace eposp::vm::detail
