// EPOS P firmware specification 10.31 - 10.37: 0x5000 - 0x5F51.
#include "eposp/canopen/entry_builder.hpp"
#include "eposp/drives/epos2/epos2_dictionary.hpp"
#include "object_areas.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <vector>

namespace eposp::device::dictionary {

// Table 28: 0x5001's codes (5 and 8 are reserved).
struct CanBitRate {
    std::uint16_t code;
    std::uint32_t bit_rate;
};
constexpr std::array<CanBitRate, 7> kCanBitRates{{{0, 1'000'000},
                                                  {1, 800'000},
                                                  {2, 500'000},
                                                  {3, 250'000},
                                                  {4, 125'000},
                                                  {6, 50'000},
                                                  {7, 20'000}}};
constexpr std::uint16_t kAutomaticBitRate = 9;

namespace {

using namespace canopen::od_types;

void add_versions(canopen::ObjectDictionary& od, std::uint16_t index, const std::string& name,
                  const std::string& part, std::uint16_t software, std::uint16_t hardware,
                  std::uint16_t application_number, std::uint16_t application_version) {
    od.add_object(index, name, kArray);
    add_entry(od, index, 1, part + " Software Version", kU16, kRO, software);
    add_entry(od, index, 2, part + " Hardware Version", kU16, kRO, hardware);
    add_entry(od, index, 3, part + " Application Number", kU16, kRO, application_number);
    add_entry(od, index, 4, part + " Application Version", kU16, kRO, application_version);
}

// 10.36: axis n's slave (table 30), the statusword its PDO brings and its controlword. Axis 0
// is the internal EPOS2 by default; the others have no slave.
void add_axes(canopen::ObjectDictionary& od) {
    for (std::uint8_t axis = 0; axis < kAxisCount; ++axis) {
        const auto index = static_cast<std::uint16_t>(kAxisIndex + axis);
        od.add_object(index, fmt::format("Axis {} Control- and Statusword", axis), kRecord);
        add_entry(od, index, 1, fmt::format("Axis {} Slave Number", axis), kU8, kRW,
                  axis == 0 ? kInternalSlave : kNoSlave)
            .range(0, kNoSlave)
            .persistent();
        add_entry(od, index, 2, fmt::format("Axis {} Statusword", axis), kU16, kRW, 0)
            .pdo_mappable();
        add_entry(od, index, 3, fmt::format("Axis {} Controlword", axis), kU16, kRW, 0)
            .pdo_mappable();
    }
}

// eposp's online access to the PLC's variables by path (docs/service-interface.md, "Variable
// access"); variable_access.cpp gives it its behaviour.
void add_variable_access(canopen::ObjectDictionary& od) {
    constexpr std::size_t kMaxText = 255; // a path or an IEC literal
    od.add_object(kVariableAccessIndex, "PLC Variable Access", kRecord);
    const std::pair<std::uint8_t, const char*> texts[] = {
        {1, "Variable Path"}, {2, "Variable Value"}, {3, "Force Value"}};
    for (const auto& [sub, name] : texts) {
        od.add_sub(kVariableAccessIndex, sub, name, canopen::DataType::VisibleString, kRW, {})
            .max_length = kMaxText;
    }
    add_entry(od, kVariableAccessIndex, 4, "Unforce", kU8, kWO, 0);
}

} // namespace

void add_manufacturer_objects(canopen::ObjectDictionary& od, const EposPDictionaryConfig& config) {
    // 10.31: takes effect at the next start, from the stored parameters.
    add_var(od, kNodeIdIndex, "Node Id", kU8, kRW, config.node_id).range(1, 127).persistent();
    // 10.32, table 28; like the node-ID, a new bit rate takes effect at the next start.
    std::vector<std::int64_t> codes;
    for (const auto& [code, rate] : kCanBitRates) {
        codes.push_back(code);
    }
    codes.push_back(kAutomaticBitRate);
    add_var(od, kCanBitRateIndex, "CAN Bitrate", kU16, kRW,
            can_bit_rate_code(config.can_bit_rate).value_or(0))
        .one_of(codes)
        .persistent();
    add_versions(od, 0x5003, "EPOS P Version", "EPOS P", kSoftwareVersion, kHardwareVersion,
                 kApplicationNumber, kApplicationVersion); // 10.33
    // 10.34: the internal module is the simulated EPOS2.
    add_versions(od, 0x5004, "Modul Version", "Modul", drives::epos2::kSoftwareVersion,
                 drives::epos2::kHardwareVersion, drives::epos2::kApplicationNumber,
                 drives::epos2::kApplicationVersion);
    add_var(od, 0x5005, "Serial Communication Frame Timeout", kU16, kRW, 500).persistent(); // 10.35
    add_axes(od);
    add_var(od, kProgramControlIndex, "Program Control", kU16, kRW, 0) // 10.37, table 31
        .one_of({0, 1, 2, 3})
        .persistent();
    add_variable_access(od);
}

} // namespace eposp::device::dictionary

namespace eposp::device {

std::optional<std::uint32_t> can_bit_rate_of(std::uint16_t code) {
    const auto found =
        std::ranges::find(dictionary::kCanBitRates, code, &dictionary::CanBitRate::code);
    return found == dictionary::kCanBitRates.end() ? std::nullopt : std::optional(found->bit_rate);
}

std::optional<std::uint16_t> can_bit_rate_code(std::uint32_t bit_rate) {
    const auto found =
        std::ranges::find(dictionary::kCanBitRates, bit_rate, &dictionary::CanBitRate::bit_rate);
    return found == dictionary::kCanBitRates.end() ? std::nullopt : std::optional(found->code);
}

} // namespace eposp::device
