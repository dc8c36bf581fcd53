#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace eposp::vm {

// The file layout (`.epx`), all little-endian:
//   header   "EPXI", u16 version, u16 0, u32 payload size, u32 CRC-32 of the payload
//   payload  sections in a fixed order, each u32 id, u32 length, contents:
//            code, arrays, static data, retain, tasks, POUs, types, symbols, bindings, imports
// Lists are a u32 count followed by the elements; strings a u32 length and the bytes.

inline constexpr std::size_t kImageHeaderSize = 16;

std::vector<std::uint8_t> write_image(const Image& image);

/// Decodes an image. Refuses anything that is not exactly what write_image produces (magic,
/// version, checksum, section order and lengths, enumerator values) with the reason; whether
/// the decoded image makes sense is verify's job.
core::Result<Image> read_image(std::span<const std::uint8_t> bytes);

} // namespace eposp::vm
