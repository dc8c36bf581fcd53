#pragma once

#include "eposp/canopen/data_type.hpp"
#include "eposp/canopen/value_codec.hpp"

#include <compare>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>

namespace eposp::canopen {

/// A value of a numeric CANopen type in a form that can be compared and printed: the signed
/// integer types as int64, the unsigned ones and BOOLEAN as uint64, REAL32/REAL64 as double.
using NumericValue = std::variant<std::int64_t, std::uint64_t, double>;

/// The value of `bytes` as `type` (INTEGER24 sign-extended and so on); nullopt when the type is
/// not numeric or the byte count is not the type's size.
std::optional<NumericValue> decode_numeric(DataType type, std::span<const std::uint8_t> bytes);

/// The bytes of `value` as `type`; nullopt when the type is not numeric or the value does not
/// fit it (300 as UNSIGNED8, -1 as UNSIGNED16, 2 as BOOLEAN, 1.5 as an integer).
std::optional<Bytes> encode_numeric(DataType type, NumericValue value);

/// Orders two values that were decoded from the same type; unordered for a NaN.
std::partial_ordering compare(const NumericValue& a, const NumericValue& b);

} // namespace eposp::canopen
