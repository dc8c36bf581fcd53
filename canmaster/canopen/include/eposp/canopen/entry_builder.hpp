#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/value_codec.hpp"

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>

namespace eposp::canopen {

/// The bytes of an integer default or limit as `type` stores it: the low bytes of its two's
/// complement, so one signature serves every integer type.
Bytes encode_integer(DataType type, std::int64_t value);

/// Describes one entry of a device's object table (a firmware manual's chapter on its
/// dictionary) on a sub-object already in a dictionary, so that each object reads as one line
/// of data.
class Entry {
public:
    explicit Entry(SubObject& sub) : sub_(sub) {}

    /// The "Value Range" column: remote writes outside it are refused (0x06090031/32).
    Entry& range(std::int64_t low, std::int64_t high);
    /// A value range given as a list of codes (a table of the spec): every other value, those
    /// beyond the list's ends too, is refused with 0x06090030 "value range of parameter
    /// exceeded" (EPOS2 FW spec table 4-12; "too high / too low" belong to min ... max ranges).
    /// So the entry has no low and high limit, which the dictionary would check first, and its
    /// EDS lists none.
    Entry& one_of(std::initializer_list<std::int64_t> values) {
        return one_of(std::span<const std::int64_t>(values.begin(), values.size()));
    }
    Entry& one_of(std::span<const std::int64_t> values);
    /// A value range bounded by another entry's current value ("1 ... Maximal Profile Velocity"):
    /// values above it are refused with 0x06090031, and with `symmetric` ("-Maximal profile
    /// velocity ... Maximal profile velocity") values below its negative with 0x06090032.
    Entry& at_most(const ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                   bool symmetric = false);
    /// Saved by 0x1010 "save", restored by 0x1011 "load".
    Entry& persistent();
    /// May be mapped into a PDO.
    Entry& pdo_mappable();
    /// A device rule beyond the table's columns (another object's value, the device's state): it
    /// is asked after the checks the entry already has (its range or list, the rules added
    /// before), and the first refusal answers the write.
    Entry& rule(SubObject::WriteHook rule);

    SubObject& sub() { return sub_; }

private:
    void set_write_check(SubObject::WriteHook check);

    SubObject& sub_;
};

/// A VAR object (sub-index 0) with an integer default.
Entry add_var(ObjectDictionary& od, std::uint16_t index, std::string name, DataType type,
              Access access, std::int64_t default_value);
/// A sub-index of an ARRAY or RECORD added with ObjectDictionary::add_object.
Entry add_entry(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index, std::string name,
                DataType type, Access access, std::int64_t default_value);
/// Makes `value` the default of an existing entry and its present value: for a default that the
/// device's configuration (its machine, its hardware variant) decides.
void set_default(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index, Bytes value);
template <typename T>
void set_default_as(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index, T value) {
    set_default(od, index, sub_index, encode(value));
}

/// An entry that a canopen service added, under the device's name for it.
Entry existing_entry(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                     std::string name);

} // namespace eposp::canopen

/// Short names for the data types and access types, so that a device's object tables read like
/// its manual's.
namespace eposp::canopen::od_types {

inline constexpr auto kI8 = DataType::Integer8;
inline constexpr auto kI16 = DataType::Integer16;
inline constexpr auto kI32 = DataType::Integer32;
inline constexpr auto kU8 = DataType::Unsigned8;
inline constexpr auto kU16 = DataType::Unsigned16;
inline constexpr auto kU32 = DataType::Unsigned32;
inline constexpr auto kU64 = DataType::Unsigned64;

inline constexpr auto kRO = Access::ReadOnly;
inline constexpr auto kRW = Access::ReadWrite;
inline constexpr auto kWO = Access::WriteOnly;
inline constexpr auto kConst = Access::Const;

inline constexpr auto kRecord = ObjectCode::Record;
inline constexpr auto kArray = ObjectCode::Array;

inline constexpr std::int64_t kI32Min = std::numeric_limits<std::int32_t>::min();
inline constexpr std::int64_t kI32Max = std::numeric_limits<std::int32_t>::max();
inline constexpr std::int64_t kU16Max = std::numeric_limits<std::uint16_t>::max();
inline constexpr std::int64_t kU32Max = std::numeric_limits<std::uint32_t>::max();

} // namespace eposp::canopen::od_types
