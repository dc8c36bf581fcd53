#pragma once

#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/data_type.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/value_codec.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace eposp::canopen {

/// A PDO carries at most one classic CAN frame's data (CiA 301 7.2.2).
inline constexpr std::size_t kMaxPdoBits = 64;

/// A PDO's payload held by value, the bytes beyond `size` zero: every TPDO packs one at every
/// SYNC, and a vector would be an allocation each time.
struct PdoPayload {
    std::array<std::uint8_t, kMaxPdoBits / 8> data{};
    std::size_t size = 0;

    std::span<const std::uint8_t> bytes() const { return {data.data(), size}; }
    friend bool operator==(const PdoPayload&, const PdoPayload&) = default;
};

/// Which way a PDO goes, seen from the device whose dictionary holds it.
enum class PdoDirection { Receive, Transmit };

/// One entry of a PDO mapping object (CiA 301 7.5.2.36 / 7.5.2.38): the mapped
/// object's index in bits 31..16, its sub-index in bits 15..8, its length in bits in 7..0.
struct MappingEntry {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    std::uint8_t bits = 0;

    static MappingEntry from_raw(std::uint32_t raw);
    std::uint32_t raw() const;
    friend bool operator==(const MappingEntry&, const MappingEntry&) = default;
};

/// CiA 301 7.4.7.1: the data type indices 0x0002..0x0007 may be mapped into an RPDO to skip
/// bits the device does not use ("dummy mapping").
bool is_dummy(MappingEntry entry);

/// Whether `entry` may be mapped into a PDO of `direction`: None, ObjectDoesNotExist (no such
/// index or sub-index, CiA 301 7.5.2.36), or NotMappable (not PDO-mappable, not writable for an
/// RPDO or readable for a TPDO, a length of 0, longer than the type, or shorter than a type
/// that is not an integer). An integer may be mapped with fewer bits than its type: a TPDO
/// sends its low bits, an RPDO stores them zero- or sign-extended.
AbortCode check_mapping_entry(const ObjectDictionary& od, MappingEntry entry,
                              PdoDirection direction);

/// A checked mapping: where each mapped value sits in the PDO's payload, bit-packed from bit 0
/// of byte 0 in sub-index order, each value least significant bit first (CiA 301 7.1.2).
class PdoMapping {
public:
    /// The mapping of `entries`, or the abort code of its first fault: those of
    /// check_mapping_entry(), or PdoLengthExceeded beyond 64 bits.
    struct Resolution;
    static Resolution resolve(const ObjectDictionary& od, std::span<const MappingEntry> entries,
                              PdoDirection direction);

    PdoMapping() = default;

    std::size_t bits() const { return bits_; }
    /// Bytes on the wire: the bits rounded up to whole bytes.
    std::size_t size() const { return (bits_ + 7) / 8; }
    bool empty() const { return fields_.empty(); }
    /// Whether the value at index/sub_index is one of the mapped ones.
    bool maps(std::uint16_t index, std::uint8_t sub_index) const;
    /// The distinct indices mapped (dummies left out), in mapping order.
    std::vector<std::uint16_t> mapped_indices() const;

    /// A TPDO's payload: the mapped values as the device reads them (ObjectDictionary::get),
    /// from the sub-objects resolve() found: valid as long as the dictionary, as a ValueRef.
    PdoPayload pack() const;
    /// Stores an RPDO's payload, of at least size() bytes, with the device's own access
    /// (ObjectDictionary::set); dummy entries are skipped.
    void unpack(ObjectDictionary& od, std::span<const std::uint8_t> payload) const;

private:
    struct Field {
        MappingEntry entry;
        DataType type = DataType::Unsigned8;
        std::size_t offset = 0;
        bool dummy = false;
        const SubObject* sub = nullptr; ///< the mapped value; none for a dummy
    };
    std::vector<Field> fields_;
    std::size_t bits_ = 0;
};

struct PdoMapping::Resolution {
    AbortCode error = AbortCode::None;
    PdoMapping mapping; ///< meaningful when error is None
};

} // namespace eposp::canopen
