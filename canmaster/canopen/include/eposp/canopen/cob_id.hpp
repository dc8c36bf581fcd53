#pragma once

#include "eposp/can/frame.hpp"

#include <cstdint>
#include <span>

namespace eposp::canopen {

// CiA 301 7.3.5: the pre-defined connection set (NMT and error control: nmt_protocol.hpp).
inline constexpr std::uint32_t kSyncCanId = 0x080;
inline constexpr std::uint32_t kEmcyCanIdBase = 0x080;

// The bits of a COB-ID entry (0x1005, 0x1014, PDO parameters; CiA 301 7.5.2).
inline constexpr std::uint32_t kCobIdInvalid = 1U << 31;  ///< EMCY, PDO: the object is off
inline constexpr std::uint32_t kCobIdGenerate = 1U << 30; ///< SYNC: this device produces it
inline constexpr std::uint32_t kCobIdExtended = 1U << 29; ///< 29-bit CAN identifier
/// The identifier and frame-format bits: what a write may not change while the entry is in use.
inline constexpr std::uint32_t kCobIdIdentifierBits = kCobIdExtended | can::kMaxExtendedId;

/// The CAN identifier an entry names: 29 bits with the frame bit set, 11 bits without.
constexpr std::uint32_t can_id(std::uint32_t cob_id) {
    return (cob_id & kCobIdExtended) != 0 ? cob_id & can::kMaxExtendedId
                                          : cob_id & can::kMaxStandardId;
}

/// Whether an entry may be written at all: an 11-bit entry leaves bits 11..28 zero, and its
/// identifier is none of those CiA 301 7.3.5 reserves for NMT, SDO, LSS and error
/// control. (0x080 is reserved for SYNC and EMCY alike, so it is allowed here.)
bool cob_id_acceptable(std::uint32_t cob_id);

/// Whether `frame` is a data frame with the identifier and format the entry names. Inline: the
/// SYNC consumer of every node asks it for every SYNC.
inline bool matches(std::uint32_t cob_id, const can::Frame& frame) {
    const bool extended = (cob_id & kCobIdExtended) != 0;
    return !frame.remote && !frame.error && frame.extended == extended &&
           frame.id == can_id(cob_id);
}

/// A data frame with the identifier and format the entry names.
can::Frame make_frame(std::uint32_t cob_id, std::span<const std::uint8_t> data);

} // namespace eposp::canopen
