#pragma once

#include <cstddef>

namespace eposp::service {

/// How many data words a frame holds on each link: v1 sends Len-1 in a byte (1 - 256 words),
/// v2 sends Len in a byte (0 - 255 words). maxon EPOS2 communication guide, "Frame structure".
inline constexpr std::size_t kV1MaxWords = 256;
inline constexpr std::size_t kV2MaxWords = 255;

} // namespace eposp::service
