#pragma once

#include "eposp/canopen/data_type.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/core/result.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace eposp::canopen {

/// A value as an EDS writes it (DefaultValue, LowLimit, HighLimit), in one canonical form so that
/// an export reads back to the same text: unsigned integers and the TIME types as 0x-hex of the
/// type's width, signed integers and BOOLEAN in decimal, reals in the shortest decimal that
/// reads back exactly, VISIBLE_STRING as its text, the other strings and DOMAIN as hex pairs.
std::string format_eds_value(DataType type, std::span<const std::uint8_t> value);

/// Reads a value as CiA 306 allows it: integers in decimal, 0x-hex or 0-octal, a hex or octal
/// signed value also as its two's complement, a sum with $NODEID (`$NODEID+0x180`, needing
/// `node_id`), reals in decimal (or 0x-hex as their IEEE 754 bits), strings and DOMAIN as
/// above, hex pairs optionally separated by spaces. An empty text is zero / empty. The error says
/// what is wrong, without a location.
core::Result<Bytes> parse_eds_value(DataType type, std::string_view text,
                                    std::optional<NodeId> node_id);

/// An unsigned number in decimal, 0x-hex or 0-octal (SupportedObjects, VendorNumber, ...).
std::optional<std::uint64_t> parse_eds_unsigned(std::string_view text);

} // namespace eposp::canopen
