#include "eposp/canopen/pdo_objects.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>
#include <string>

namespace eposp::canopen {
namespace {

constexpr std::uint8_t kMappingCountSub = 0;

// The parameter limits that the write hooks need besides the dictionary.
struct Limits {
    PdoDirection direction = PdoDirection::Receive;
    std::size_t number = 1;
    std::uint8_t mapping_entries = 8;
    bool extended_ids = true;
    std::optional<CanIdRange> can_id_range;
    std::vector<std::uint8_t> transmission_types; ///< empty: every type CiA 301 allows
};

bool accepted_transmission_type(const Limits& limits, std::uint8_t type) {
    return valid_transmission_type(limits.direction, type) &&
           (limits.transmission_types.empty() ||
            std::ranges::find(limits.transmission_types, type) != limits.transmission_types.end());
}

bool in(CanIdRange range, std::uint32_t id) {
    return id >= range.first && id <= range.last;
}

bool pdo_valid(const ObjectDictionary& od, const Limits& limits) {
    const auto index = pdo_communication_index(limits.direction, limits.number);
    return PdoCobId{od.get_as<std::uint32_t>(index, kPdoCobIdSub)}.valid();
}

// CiA 301 7.5.2.35: bits 0..29 are fixed while the PDO exists; the identifier must fit its
// format and, once valid, must not be one that other services own. An invalid entry may hold
// any identifier, 0 included (EPOS2 FW spec table 8-76).
AbortCode check_cob_id(const ObjectDictionary& od, const Limits& limits, PdoCobId next) {
    const auto index = pdo_communication_index(limits.direction, limits.number);
    const PdoCobId now{od.get_as<std::uint32_t>(index, kPdoCobIdSub)};
    if (now.valid() && next.valid() && ((now.raw ^ next.raw) & kCobIdIdentifierBits) != 0) {
        return AbortCode::InvalidValue;
    }
    if (next.extended()) {
        return limits.extended_ids ? AbortCode::None : AbortCode::InvalidValue;
    }
    if (next.valid()) {
        const bool usable = cob_id_acceptable(next.raw) &&
                            (!limits.can_id_range || in(*limits.can_id_range, next.can_id()));
        return usable ? AbortCode::None : AbortCode::InvalidValue;
    }
    constexpr std::uint32_t kBits11To28 = can::kMaxExtendedId & ~can::kMaxStandardId;
    return (next.raw & kBits11To28) == 0 ? AbortCode::None : AbortCode::InvalidValue;
}

// CiA 301 7.5.2.36 / 7.5.2.38: sub-index 0 says how many entries are in use; changing it
// checks the whole mapping as it would become.
AbortCode check_mapping_count(const ObjectDictionary& od, const Limits& limits,
                              std::uint8_t count) {
    if (pdo_valid(od, limits)) {
        return AbortCode::ParameterIncompatibility;
    }
    if (count > limits.mapping_entries) {
        return AbortCode::PdoLengthExceeded;
    }
    const auto index = pdo_mapping_index(limits.direction, limits.number);
    std::vector<MappingEntry> entries;
    for (std::uint8_t sub = 1; sub <= count; ++sub) {
        entries.push_back(MappingEntry::from_raw(od.get_as<std::uint32_t>(index, sub)));
    }
    return PdoMapping::resolve(od, entries, limits.direction).error;
}

AbortCode check_mapping_entry_write(const ObjectDictionary& od, const Limits& limits,
                                    std::uint32_t raw) {
    const auto index = pdo_mapping_index(limits.direction, limits.number);
    if (pdo_valid(od, limits) || od.get_as<std::uint8_t>(index, kMappingCountSub) != 0) {
        return AbortCode::ParameterIncompatibility;
    }
    if (raw == 0) {
        return AbortCode::None; // clearing an entry
    }
    return check_mapping_entry(od, MappingEntry::from_raw(raw), limits.direction);
}

// Installs `check` as the write hook of `sub`, unless it has one (a device's own rule, or the
// rules installed before) or a type of another size (an EDS's own idea of the entry). Every hook
// accepts the value the object already holds: a configuration tool may write a whole
// configuration again, unchanged, while the PDO is valid.
template <typename T, typename Check>
void guard(const ObjectDictionary& od, std::uint16_t index, SubObject* sub, Check check) {
    if (sub == nullptr || sub->on_write || fixed_size(sub->type) != sizeof(T)) {
        return;
    }
    sub->on_write = [&od, index, sub_index = sub->sub_index,
                     check](std::span<const std::uint8_t> data) {
        const T value = decode<T>(data);
        if (value == od.get_as<T>(index, sub_index)) {
            return AbortCode::None;
        }
        return check(value);
    };
}

// Inhibit time and SYNC start value (CiA 301 7.5.2.37): fixed while the PDO exists.
AbortCode only_while_invalid(const ObjectDictionary& od, const Limits& limits) {
    return pdo_valid(od, limits) ? AbortCode::InvalidValue : AbortCode::None;
}

std::string pdo_name(const Limits& limits) {
    return fmt::format("{} PDO {}",
                       limits.direction == PdoDirection::Receive ? "Receive" : "Transmit",
                       limits.number);
}

void add_persistent(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                    std::string name, DataType type, Bytes value) {
    od.add_sub(index, sub_index, std::move(name), type, Access::ReadWrite, std::move(value))
        .persistent = true;
}

// CiA 301 7.5.2.35 / 7.5.2.37: the rules of the communication parameters that exist.
void guard_communication(ObjectDictionary& od, const Limits& limits) {
    const auto index = pdo_communication_index(limits.direction, limits.number);
    guard<std::uint32_t>(od, index, od.find(index, kPdoCobIdSub), [&od, limits](std::uint32_t raw) {
        return check_cob_id(od, limits, PdoCobId{raw});
    });
    guard<std::uint8_t>(
        od, index, od.find(index, kPdoTransmissionTypeSub), [limits](std::uint8_t value) {
            return accepted_transmission_type(limits, value) ? AbortCode::None
                                                             : AbortCode::InvalidValue;
        });
    if (limits.direction == PdoDirection::Receive) {
        return; // sub-indices 3 and 6 are not used by RPDOs
    }
    guard<std::uint16_t>(od, index, od.find(index, kPdoInhibitTimeSub),
                         [&od, limits](std::uint16_t) { return only_while_invalid(od, limits); });
    guard<std::uint8_t>(od, index, od.find(index, kPdoSyncStartSub),
                        [&od, limits](std::uint8_t value) {
                            return value > kSyncCyclicMax ? AbortCode::InvalidValue
                                                          : only_while_invalid(od, limits);
                        });
}

// CiA 301 7.5.2.36 / 7.5.2.38: the mapping procedure, on the entries that exist.
void guard_mapping(ObjectDictionary& od, const Limits& limits) {
    const auto index = pdo_mapping_index(limits.direction, limits.number);
    for (std::uint8_t sub = 1; sub <= limits.mapping_entries; ++sub) {
        guard<std::uint32_t>(od, index, od.find(index, sub), [&od, limits](std::uint32_t value) {
            return check_mapping_entry_write(od, limits, value);
        });
    }
    guard<std::uint8_t>(
        od, index, od.find(index, kMappingCountSub),
        [&od, limits](std::uint8_t value) { return check_mapping_count(od, limits, value); });
}

void add_communication(ObjectDictionary& od, const Limits& limits, const PdoDefaults& defaults,
                       const PdoObjectsConfig& config) {
    const auto index = pdo_communication_index(limits.direction, limits.number);
    od.add_object(index, pdo_name(limits) + " Parameter", ObjectCode::Record);
    add_persistent(od, index, kPdoCobIdSub, "COB-ID", DataType::Unsigned32,
                   encode(defaults.cob_id));
    add_persistent(od, index, kPdoTransmissionTypeSub, "Transmission type", DataType::Unsigned8,
                   encode(defaults.transmission_type));
    const bool receive = limits.direction == PdoDirection::Receive;
    if (!receive) {
        add_persistent(od, index, kPdoInhibitTimeSub, "Inhibit time", DataType::Unsigned16,
                       encode(defaults.inhibit_time));
    }
    // CiA 301 7.5.2.35: an RPDO's event timer is its deadline.
    if (receive ? config.rpdo_event_timer : config.tpdo_event_timer) {
        add_persistent(od, index, kPdoEventTimerSub, "Event timer", DataType::Unsigned16,
                       encode(defaults.event_timer));
    }
    if (!receive && config.tpdo_sync_start) {
        add_persistent(od, index, kPdoSyncStartSub, "SYNC start value", DataType::Unsigned8,
                       encode(defaults.sync_start));
    }
    guard_communication(od, limits);
}

void add_mapping(ObjectDictionary& od, const Limits& limits, const PdoDefaults& defaults) {
    if (defaults.mapping.size() > limits.mapping_entries) {
        throw std::invalid_argument(fmt::format("{}: {} default mapping entries, {} supported",
                                                pdo_name(limits), defaults.mapping.size(),
                                                limits.mapping_entries));
    }
    const auto index = pdo_mapping_index(limits.direction, limits.number);
    od.add_object(index, pdo_name(limits) + " Mapping", ObjectCode::Record);
    for (std::uint8_t sub = 1; sub <= limits.mapping_entries; ++sub) {
        const std::uint32_t raw = sub <= defaults.mapping.size() ? defaults.mapping[sub - 1] : 0;
        add_persistent(od, index, sub, fmt::format("Mapped object {}", sub), DataType::Unsigned32,
                       encode(raw));
    }
    // Sub-index 0 is the number of mapped objects here, not the highest sub-index: a writable
    // value that add_sub() no longer touches once the entries are in.
    SubObject& count = *od.find(index, kMappingCountSub);
    count.name = "Number of mapped objects";
    count.access = Access::ReadWrite;
    count.persistent = true;
    count.default_value = encode(static_cast<std::uint8_t>(defaults.mapping.size()));
    count.value = count.default_value;
    guard_mapping(od, limits);
}

void add_pdos(ObjectDictionary& od, PdoDirection direction, const std::vector<PdoDefaults>& pdos,
              const PdoObjectsConfig& config) {
    const bool receive = direction == PdoDirection::Receive;
    for (std::size_t i = 0; i < pdos.size(); ++i) {
        const Limits limits{direction,
                            config.first_number + i,
                            config.mapping_entries,
                            config.extended_ids,
                            config.can_id_range,
                            receive ? config.rpdo_transmission_types
                                    : config.tpdo_transmission_types};
        add_communication(od, limits, pdos[i], config);
        add_mapping(od, limits, pdos[i]);
    }
}

std::uint16_t pdo_index(std::uint16_t base, std::size_t number) {
    if (number == 0 || number > kMaxPdoNumber) {
        throw std::out_of_range(fmt::format("PDO number {} is not 1..{}", number, kMaxPdoNumber));
    }
    return static_cast<std::uint16_t>(base + number - 1);
}

template <typename T>
T stored_or_zero(const ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index) {
    return od.find(index, sub_index) == nullptr ? T{0} : od.get_as<T>(index, sub_index);
}

// CiA 301 7.3.5: the predefined connection set gives PDOs 1..4 function codes 0x180 / 0x200
// apart by 0x100 per PDO.
std::uint32_t predefined_id(PdoDirection direction, std::size_t number, NodeId node) {
    const std::uint32_t base = direction == PdoDirection::Receive ? 0x200 : 0x180;
    return base + 0x100 * static_cast<std::uint32_t>(number - 1) + node;
}

} // namespace

std::uint16_t pdo_communication_index(PdoDirection direction, std::size_t number) {
    return pdo_index(direction == PdoDirection::Receive ? kRpdoCommunicationBase
                                                        : kTpdoCommunicationBase,
                     number);
}

std::uint16_t pdo_mapping_index(PdoDirection direction, std::size_t number) {
    return pdo_index(direction == PdoDirection::Receive ? kRpdoMappingBase : kTpdoMappingBase,
                     number);
}

bool valid_transmission_type(PdoDirection direction, std::uint8_t type) {
    if (type <= kSyncCyclicMax || type >= kEventDrivenManufacturer) {
        return true;
    }
    return direction == PdoDirection::Transmit &&
           (type == kRtrSynchronous || type == kRtrEventDriven);
}

PdoObjectsConfig cia301_pdo_defaults(NodeId node, std::size_t rpdo_count, std::size_t tpdo_count) {
    constexpr std::size_t kPredefined = 4;
    PdoObjectsConfig config;
    for (std::size_t n = 1; n <= rpdo_count; ++n) {
        const std::uint32_t id =
            n <= kPredefined ? predefined_id(PdoDirection::Receive, n, node) : 0;
        config.rpdos.push_back({.cob_id = PdoCobId::kInvalid | id, .mapping = {}});
    }
    for (std::size_t n = 1; n <= tpdo_count; ++n) {
        const std::uint32_t id =
            n <= kPredefined ? predefined_id(PdoDirection::Transmit, n, node) : 0;
        config.tpdos.push_back(
            {.cob_id = PdoCobId::kInvalid | PdoCobId::kNoRtr | id, .mapping = {}});
    }
    return config;
}

PdoObjectsConfig epos2_pdo_defaults(NodeId node) {
    const auto rx = [node](std::size_t n) {
        return predefined_id(PdoDirection::Receive, n, node);
    };
    const auto tx = [node](std::size_t n) {
        return predefined_id(PdoDirection::Transmit, n, node);
    };
    constexpr std::uint32_t kNotValidNoRtr = PdoCobId::kInvalid | PdoCobId::kNoRtr;
    PdoObjectsConfig config;
    // EPOS2 FW spec 8.2.18 - 8.2.25: controlword with mode, target position or target velocity.
    config.rpdos = {
        {.cob_id = rx(1), .mapping = {0x6040'0010}},
        {.cob_id = rx(2), .mapping = {0x6040'0010, 0x6060'0008}},
        {.cob_id = rx(3), .mapping = {0x6040'0010, 0x607A'0020}},
        {.cob_id = rx(4), .mapping = {0x6040'0010, 0x60FF'0020}},
    };
    // 8.2.26 - 8.2.33: statusword with mode display, actual position or actual velocity;
    // only TPDO 1 is valid. (8.2.32 prints 0x1A02 sub 2 as "0x6064020": position actual value
    // 0x6064, 32 bits.)
    config.tpdos = {
        {.cob_id = PdoCobId::kNoRtr | tx(1), .mapping = {0x6041'0010}},
        {.cob_id = kNotValidNoRtr | tx(2), .mapping = {0x6041'0010, 0x6061'0008}},
        {.cob_id = kNotValidNoRtr | tx(3), .mapping = {0x6041'0010, 0x6064'0020}},
        {.cob_id = kNotValidNoRtr | tx(4),
         .transmission_type = kRtrEventDriven,
         .mapping = {0x6041'0010, 0x606C'0020}},
    };
    config.mapping_entries = 8;
    config.tpdo_event_timer = false;
    config.rpdo_event_timer = false;
    config.tpdo_sync_start = false;
    config.extended_ids = false; // tables 8-75 / 8-78: bit 29 is 0 (CAN base frame)
    config.can_id_range = CanIdRange{0x181, 0x57F};
    return config;
}

void add_pdo_objects(ObjectDictionary& od, const PdoObjectsConfig& config) {
    const std::size_t last =
        config.first_number - 1 + std::max(config.rpdos.size(), config.tpdos.size());
    if (config.first_number == 0 || last > kMaxPdoNumber) {
        throw std::invalid_argument("add_pdo_objects: PDO numbers are 1..512");
    }
    add_pdos(od, PdoDirection::Receive, config.rpdos, config);
    add_pdos(od, PdoDirection::Transmit, config.tpdos, config);
}

void add_pdo_objects(ObjectDictionary& od, NodeId node, std::size_t rpdo_count,
                     std::size_t tpdo_count) {
    add_pdo_objects(od, cia301_pdo_defaults(node, rpdo_count, tpdo_count));
}

void enforce_pdo_rules(ObjectDictionary& od, std::size_t first_number) {
    for (const auto direction : {PdoDirection::Receive, PdoDirection::Transmit}) {
        const std::size_t count = count_pdos(od, direction, first_number);
        for (std::size_t number = first_number; number < first_number + count; ++number) {
            const Object* mapping = od.find(pdo_mapping_index(direction, number));
            const std::uint8_t entries =
                mapping == nullptr || mapping->subs.empty() ? 0 : mapping->subs.rbegin()->first;
            Limits limits;
            limits.direction = direction;
            limits.number = number;
            limits.mapping_entries = entries;
            guard_communication(od, limits);
            guard_mapping(od, limits);
        }
    }
}

std::size_t count_pdos(const ObjectDictionary& od, PdoDirection direction,
                       std::size_t first_number) {
    std::size_t count = 0;
    while (first_number + count <= kMaxPdoNumber &&
           od.find(pdo_communication_index(direction, first_number + count)) != nullptr) {
        ++count;
    }
    return count;
}

PdoCommunication read_pdo_communication(const ObjectDictionary& od, PdoDirection direction,
                                        std::size_t number) {
    const auto index = pdo_communication_index(direction, number);
    PdoCommunication comm;
    comm.cob_id = PdoCobId{stored_or_zero<std::uint32_t>(od, index, kPdoCobIdSub)};
    comm.transmission_type = stored_or_zero<std::uint8_t>(od, index, kPdoTransmissionTypeSub);
    // CiA 301 7.5.2.37: inhibit time in multiples of 100 us, event timer in ms.
    comm.inhibit_time = std::chrono::microseconds(100) *
                        stored_or_zero<std::uint16_t>(od, index, kPdoInhibitTimeSub);
    comm.event_timer =
        std::chrono::milliseconds(stored_or_zero<std::uint16_t>(od, index, kPdoEventTimerSub));
    comm.sync_start = stored_or_zero<std::uint8_t>(od, index, kPdoSyncStartSub);
    return comm;
}

std::vector<MappingEntry> read_pdo_mapping(const ObjectDictionary& od, PdoDirection direction,
                                           std::size_t number) {
    const auto index = pdo_mapping_index(direction, number);
    const auto count = stored_or_zero<std::uint8_t>(od, index, kMappingCountSub);
    std::vector<MappingEntry> entries;
    for (std::uint8_t sub = 1; sub <= count; ++sub) {
        entries.push_back(MappingEntry::from_raw(stored_or_zero<std::uint32_t>(od, index, sub)));
    }
    return entries;
}

} // namespace eposp::canopen
