#pragma once

#include "eposp/canopen/cob_id.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/pdo_mapping.hpp"
#include "eposp/core/time.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace eposp::canopen {

// CiA 301 7.5.2.35 - 7.5.2.38: the communication and mapping parameters of PDO n (1-based) are
// at base + n - 1, up to 512 PDOs each way.
inline constexpr std::uint16_t kRpdoCommunicationBase = 0x1400;
inline constexpr std::uint16_t kRpdoMappingBase = 0x1600;
inline constexpr std::uint16_t kTpdoCommunicationBase = 0x1800;
inline constexpr std::uint16_t kTpdoMappingBase = 0x1A00;
inline constexpr std::size_t kMaxPdoNumber = 512;

std::uint16_t pdo_communication_index(PdoDirection direction, std::size_t number);
std::uint16_t pdo_mapping_index(PdoDirection direction, std::size_t number);

// Sub-indices of a communication parameter record (CiA 301 7.5.2.35 / 7.5.2.37). Sub-index 4
// is reserved: it does not exist.
inline constexpr std::uint8_t kPdoCobIdSub = 1;
inline constexpr std::uint8_t kPdoTransmissionTypeSub = 2;
inline constexpr std::uint8_t kPdoInhibitTimeSub = 3;
inline constexpr std::uint8_t kPdoEventTimerSub = 5;
inline constexpr std::uint8_t kPdoSyncStartSub = 6;

/// The COB-ID entry of a PDO (CiA 301 7.5.2.35; EPOS2 FW spec tables 8-75, 8-78): bit 31 set
/// when the PDO does not exist (is invalid), bit 30 set when it may not be requested by RTR,
/// bit 29 set for a 29-bit CAN-ID (cob_id.hpp).
struct PdoCobId {
    static constexpr std::uint32_t kInvalid = kCobIdInvalid;
    static constexpr std::uint32_t kNoRtr = std::uint32_t{1} << 30;
    static constexpr std::uint32_t kExtended = kCobIdExtended;

    std::uint32_t raw = kInvalid;

    bool valid() const { return (raw & kInvalid) == 0; }
    bool rtr_allowed() const { return (raw & kNoRtr) == 0; }
    bool extended() const { return (raw & kExtended) != 0; }
    std::uint32_t can_id() const { return canopen::can_id(raw); }
};

// CiA 301 7.5.2.37: transmission types. 241..251 are reserved; 252 and 253 exist for
// TPDOs only.
inline constexpr std::uint8_t kSyncAcyclic = 0;
inline constexpr std::uint8_t kSyncCyclicMax = 240;
inline constexpr std::uint8_t kRtrSynchronous = 252;
inline constexpr std::uint8_t kRtrEventDriven = 253;
inline constexpr std::uint8_t kEventDrivenManufacturer = 254;
inline constexpr std::uint8_t kEventDrivenProfile = 255;
bool valid_transmission_type(PdoDirection direction, std::uint8_t type);

/// The default values of one PDO's parameters. TPDO-only entries are ignored for RPDOs.
struct PdoDefaults {
    std::uint32_t cob_id = PdoCobId::kInvalid;
    std::uint8_t transmission_type = kEventDrivenProfile;
    std::uint16_t inhibit_time = 0;     ///< TPDO, in 100 us
    std::uint16_t event_timer = 0;      ///< TPDO event timer, RPDO deadline; ms, 0 = off
    std::uint8_t sync_start = 0;        ///< TPDO, 0 = not used
    std::vector<std::uint32_t> mapping; ///< raw entries; sub-index 0 defaults to their number
};

/// An inclusive range of 11-bit CAN-IDs.
struct CanIdRange {
    std::uint32_t first = 0;
    std::uint32_t last = 0;
};

/// Which PDOs a device has, their defaults, and the device's limits on the parameters.
struct PdoObjectsConfig {
    std::vector<PdoDefaults> rpdos;   ///< RPDO n at [n - 1]
    std::vector<PdoDefaults> tpdos;   ///< TPDO n at [n - 1]
    std::uint8_t mapping_entries = 8; ///< sub-indices 1..n of every mapping object
    bool tpdo_event_timer = true;     ///< TPDO communication sub-index 5 exists
    bool rpdo_event_timer = true;     ///< RPDO communication sub-index 5 (deadline) exists
    bool tpdo_sync_start = true;      ///< TPDO communication sub-index 6 exists
    bool extended_ids = true;         ///< a COB-ID may set bit 29 (29-bit CAN-ID)
    /// The CAN-IDs a valid PDO may use, on top of the IDs CiA 301 7.3.5 restricts.
    std::optional<CanIdRange> can_id_range;
    /// The number of the first PDO of `rpdos` and `tpdos`: 257 puts them at 0x1500 / 0x1700 and
    /// 0x1900 / 0x1B00 (the EPOS P's internal PDOs).
    std::size_t first_number = 1;
    /// The transmission types a device accepts (EPOS P tables 15 and 20); empty: every type
    /// CiA 301 allows for the direction. Others are refused with InvalidValue.
    std::vector<std::uint8_t> rpdo_transmission_types;
    std::vector<std::uint8_t> tpdo_transmission_types;
};

/// CiA 301 defaults for a device without a profile: the predefined connection set's COB-IDs
/// (7.3.5: TPDO n at 0x180 + 0x100 (n - 1) + node-ID, RPDO n at 0x200 + ...) for PDOs 1..4,
/// none beyond; every PDO invalid, without mapping, event-driven (255), TPDOs without RTR.
PdoObjectsConfig cia301_pdo_defaults(NodeId node, std::size_t rpdo_count, std::size_t tpdo_count);

/// The maxon EPOS2's four RPDOs and four TPDOs exactly as its firmware specification lists
/// them (8.2.18 - 8.2.33): COB-IDs, transmission types, default mappings, sub-indices 1..3 of
/// the TPDO records only, 8 mapping entries, 11-bit CAN-IDs 0x181..0x57F.
PdoObjectsConfig epos2_pdo_defaults(NodeId node);

/// Adds the communication (0x1400+, 0x1800+) and mapping (0x1600+, 0x1A00+) objects of every
/// PDO in `config` to `od`, persistent, with write hooks that enforce CiA 301's rules:
/// - COB-ID: bits 0..29 change only while the PDO is invalid (InvalidValue); a valid PDO's
///   entry must be cob_id_acceptable() and within config.can_id_range; bits 11..28 of an
///   11-bit COB-ID, or bit 29 where extended IDs are not supported: InvalidValue.
/// - transmission type: reserved values, 252/253 for an RPDO, and a type outside the config's
///   list: InvalidValue.
/// - inhibit time and SYNC start value change only while the PDO is invalid (InvalidValue);
///   a SYNC start value above 240: InvalidValue.
/// - mapping (CiA 301 7.5.2.36 procedure): sub-index 0 and the entries change only while the
///   PDO is invalid, the entries only while sub-index 0 is 0 (ParameterIncompatibility); an
///   entry must pass check_mapping_entry(); sub-index 0 above the entries there are
///   (PdoLengthExceeded), an entry among 1..n that does not pass, or more than 64 bits
///   (PdoLengthExceeded) refuse the write of sub-index 0. Writing the current value is always
///   accepted, so that a configuration can be written again unchanged.
/// The dictionary must outlive its hooks and not move (they refer to it).
void add_pdo_objects(ObjectDictionary& od, const PdoObjectsConfig& config);
/// add_pdo_objects(od, cia301_pdo_defaults(node, rpdo_count, tpdo_count)).
void add_pdo_objects(ObjectDictionary& od, NodeId node, std::size_t rpdo_count,
                     std::size_t tpdo_count);

/// The rules of add_pdo_objects() on the PDO objects `od` already has (e.g. imported from an
/// EDS), PDOs first_number, first_number + 1, ...: each sub-object without a write hook of its
/// own and of the expected size gets the rule's hook. The limits come from the dictionary: as
/// many mapping entries as the mapping object has sub-indices, 29-bit CAN-IDs allowed, every
/// transmission type CiA 301 allows. Objects add_pdo_objects() made keep their hooks.
void enforce_pdo_rules(ObjectDictionary& od, std::size_t first_number = 1);

/// The number of PDOs of `direction` in `od`: its communication objects n = first_number,
/// first_number + 1, ... present.
std::size_t count_pdos(const ObjectDictionary& od, PdoDirection direction,
                       std::size_t first_number = 1);

/// A PDO's communication parameters as the dictionary holds them now; a missing sub-index
/// reads as 0.
struct PdoCommunication {
    PdoCobId cob_id;
    std::uint8_t transmission_type = kEventDrivenProfile;
    core::Duration inhibit_time{};
    core::Duration event_timer{};
    std::uint8_t sync_start = 0;
};
PdoCommunication read_pdo_communication(const ObjectDictionary& od, PdoDirection direction,
                                        std::size_t number);
/// The entries 1..n of a PDO's mapping, n being the value of sub-index 0.
std::vector<MappingEntry> read_pdo_mapping(const ObjectDictionary& od, PdoDirection direction,
                                           std::size_t number);

} // namespace eposp::canopen
