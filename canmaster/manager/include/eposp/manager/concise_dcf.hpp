#pragma once

#include "eposp/core/result.hpp"
#include "eposp/manager/network_list.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace eposp::manager {

/// The concise DCF of CiA 302-3 (the format of 0x1F22): the number of entries as UNSIGNED32,
/// then per entry its index (UNSIGNED16), sub-index (UNSIGNED8), data size in bytes
/// (UNSIGNED32) and data, all little-endian.
std::vector<std::uint8_t> encode_concise_dcf(std::span<const ConfigurationWrite> writes);

/// Reads a concise DCF; the error names the byte where it stops making sense (a truncated
/// entry, a size beyond the file, bytes after the last entry).
core::Result<std::vector<ConfigurationWrite>> decode_concise_dcf(std::span<const std::uint8_t> bytes);

} // namespace eposp::manager
