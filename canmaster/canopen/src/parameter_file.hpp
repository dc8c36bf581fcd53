#pragma once

#include "eposp/canopen/value_codec.hpp"
#include "eposp/core/result.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace eposp::canopen {

/// The contents of a parameter store file: the persistent values of a dictionary and the
/// identity of the layout they belong to.
struct ParameterFile {
    struct Entry {
        std::uint16_t index = 0;
        std::uint8_t sub_index = 0;
        Bytes value;
        bool operator==(const Entry&) const = default;
    };
    std::uint32_t layout_id = 0;
    std::vector<Entry> entries;
    bool operator==(const ParameterFile&) const = default;
};

/// Little-endian: the magic "EPOSPPAR", a format version (UNSIGNED16), the layout id and entry
/// count (UNSIGNED32), per entry index (UNSIGNED16), sub-index (UNSIGNED8), length (UNSIGNED32)
/// and bytes, then a CRC-32 of everything before it.
Bytes serialize(const ParameterFile& file);
/// Any damage (truncation, a flipped bit, trailing bytes, another format) is an error.
core::Result<ParameterFile> parse_parameter_file(std::span<const std::uint8_t> bytes);

/// The CRC-32 (IEEE 802.3, as zlib) of `bytes`.
std::uint32_t crc32(std::span<const std::uint8_t> bytes);

} // namespace eposp::canopen
