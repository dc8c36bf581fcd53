#pragma once

#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <initializer_list>
#include <string>

namespace eposp::drives::epos2 {

/// The bytes of an integer default or limit as `type` stores it: the low bytes of its two's
/// complement, so one signature serves every integer type of table 8-68.
canopen::Bytes encode_integer(canopen::DataType type, std::int64_t value);

/// Describes one entry of the EPOS2 object table (8.1.1) on a sub-object already in a
/// dictionary, so that each object of chapter 8 reads as one line of data.
class Entry {
public:
    explicit Entry(canopen::SubObject& sub) : sub_(sub) {}

    /// The "Value Range" column: remote writes outside it are refused (0x06090031/32).
    Entry& range(std::int64_t low, std::int64_t high);
    /// A value range given as a list of codes (a table of the spec): other values are refused
    /// with 0x06090030 "value range of parameter exceeded".
    Entry& one_of(std::initializer_list<std::int64_t> values);
    /// A value range bounded by another entry's current value ("1 ... Maximal Profile Velocity"):
    /// values above it are refused with 0x06090031, and with `symmetric` ("-Maximal profile
    /// velocity ... Maximal profile velocity") values below its negative with 0x06090032.
    Entry& at_most(const canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                   bool symmetric = false);
    /// "Subindex of persistent parameters" (8.1.1): saved by 0x1010, restored by 0x1011.
    Entry& persistent();
    /// "PDO mappable parameters" (8.1.1).
    Entry& pdo_mappable();

    canopen::SubObject& sub() { return sub_; }

private:
    void set_write_check(canopen::SubObject::WriteHook check);

    canopen::SubObject& sub_;
};

/// A VAR object (sub-index 0) with an integer default.
Entry add_var(canopen::ObjectDictionary& od, std::uint16_t index, std::string name,
              canopen::DataType type, canopen::Access access, std::int64_t default_value);
/// A sub-index of an ARRAY or RECORD added with ObjectDictionary::add_object.
Entry add_entry(canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                std::string name, canopen::DataType type, canopen::Access access,
                std::int64_t default_value);
/// An entry that a canmaster service added, with the EPOS2's name for it.
Entry existing_entry(canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                     std::string name);

} // namespace eposp::drives::epos2
