#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace eposp::compiler {

/// How many bytes `text` starts with that are ASCII (below 0x80), looked at eight at a time: the
/// whole of nearly every source file, which then needs no decoding byte by byte.
inline std::size_t ascii_prefix(std::string_view text) {
    std::size_t i = 0;
    for (; i + 8 <= text.size(); i += 8) {
        std::uint64_t word = 0;
        std::memcpy(&word, text.data() + i, sizeof word);
        if ((word & 0x8080808080808080U) != 0) {
            break;
        }
    }
    while (i < text.size() && static_cast<unsigned char>(text[i]) < 0x80) {
        ++i;
    }
    return i;
}

} // namespace eposp::compiler
