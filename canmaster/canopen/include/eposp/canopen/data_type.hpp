#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace eposp::canopen {

/// The static data types of CiA 301 (7.4.7.1, table 44), by their object dictionary index, which
/// is also how EDS files name them (DataType=0x0007).
enum class DataType : std::uint16_t {
    Boolean = 0x0001,
    Integer8 = 0x0002,
    Integer16 = 0x0003,
    Integer32 = 0x0004,
    Unsigned8 = 0x0005,
    Unsigned16 = 0x0006,
    Unsigned32 = 0x0007,
    Real32 = 0x0008,
    VisibleString = 0x0009,
    OctetString = 0x000A,
    UnicodeString = 0x000B,
    TimeOfDay = 0x000C,
    TimeDifference = 0x000D,
    Domain = 0x000F,
    Integer24 = 0x0010,
    Real64 = 0x0011,
    Integer40 = 0x0012,
    Integer48 = 0x0013,
    Integer56 = 0x0014,
    Integer64 = 0x0015,
    Unsigned24 = 0x0016,
    Unsigned40 = 0x0018,
    Unsigned48 = 0x0019,
    Unsigned56 = 0x001A,
    Unsigned64 = 0x001B,
};

/// The size in bytes of a value of a fixed-size type; nullopt for strings and DOMAIN, whose
/// size is that of the value. BOOLEAN occupies one byte in the dictionary (one bit in a PDO).
std::optional<std::size_t> fixed_size(DataType type);
/// The size in bits a PDO mapping uses for the type (1 for BOOLEAN).
std::optional<std::size_t> mapping_bits(DataType type);
bool is_signed_integer(DataType type);
bool is_unsigned_integer(DataType type);
bool is_real(DataType type);
/// For the integer and real types, plus BOOLEAN: values that have an order and a range.
bool is_numeric(DataType type);
std::string_view to_string(DataType type); ///< "UNSIGNED32", as CiA 301 spells it
std::optional<DataType> data_type_from_index(std::uint16_t index);

} // namespace eposp::canopen
