#pragma once

#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <limits>

// Short names for the data types and access types of tables 8-68 / 8-69, so that the object
// tables of the area files read like the specification's object tables.
namespace eposp::drives::epos2::od_types {

inline constexpr auto kI8 = canopen::DataType::Integer8;
inline constexpr auto kI16 = canopen::DataType::Integer16;
inline constexpr auto kI32 = canopen::DataType::Integer32;
inline constexpr auto kU8 = canopen::DataType::Unsigned8;
inline constexpr auto kU16 = canopen::DataType::Unsigned16;
inline constexpr auto kU32 = canopen::DataType::Unsigned32;
inline constexpr auto kU64 = canopen::DataType::Unsigned64;

inline constexpr auto kRO = canopen::Access::ReadOnly;
inline constexpr auto kRW = canopen::Access::ReadWrite;
inline constexpr auto kWO = canopen::Access::WriteOnly;
inline constexpr auto kConst = canopen::Access::Const;

inline constexpr auto kRecord = canopen::ObjectCode::Record;
inline constexpr auto kArray = canopen::ObjectCode::Array;

inline constexpr std::int64_t kI32Min = std::numeric_limits<std::int32_t>::min();
inline constexpr std::int64_t kI32Max = std::numeric_limits<std::int32_t>::max();
inline constexpr std::int64_t kU16Max = std::numeric_limits<std::uint16_t>::max();
inline constexpr std::int64_t kU32Max = std::numeric_limits<std::uint32_t>::max();

} // namespace eposp::drives::epos2::od_types
