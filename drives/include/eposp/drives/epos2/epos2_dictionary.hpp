#pragma once

#include "eposp/canopen/device_info.hpp"
#include "eposp/canopen/node.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/parameter_store.hpp"
#include "eposp/canopen/store_restore_objects.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace eposp::drives::epos2 {

// EPOS2 FW spec 8.2.15 / 8.2.37: the simulated device is an EPOS2 24/5 (hardware version
// 0x622x) running firmware 0x2126, the newest version of chapter 9, without an application.
inline constexpr std::uint32_t kMaxonVendorId = 0x0000'00FB;
inline constexpr std::uint16_t kSoftwareVersion = 0x2126;
inline constexpr std::uint16_t kHardwareVersion = 0x6220;
inline constexpr std::uint16_t kApplicationNumber = 0x0000;
inline constexpr std::uint16_t kApplicationVersion = 0x0000;
/// 8.2.1: CiA 402 (0x0192) servo drive (0x0002).
inline constexpr std::uint32_t kDeviceType = 0x0002'0192;

/// Table 8-81: the code 0x2001 / 0x200A give a bit rate an EPOS2 runs at (0 for 1 Mbit/s … 7 for
/// 20 kbit/s); nothing for one it cannot (10 kbit/s, 100 kbit/s, …).
std::optional<std::uint16_t> bit_rate_code(std::uint32_t bit_rate);

struct Epos2DictionaryConfig {
    canopen::NodeId node_id = 1; ///< 0x2000 and the node-ID-based COB-IDs (8.2.34)
    /// bit/s of the bus the node runs on: what automatic bit rate detection finds (0x200A, 8.2.42)
    std::uint32_t bit_rate = 1'000'000;
    std::uint64_t serial_number = 0; ///< 0x2004; 0x1018 sub 4 shows its low 32 bits (8.2.15)
    /// The non-volatile memory of 0x1010 / 0x1011: nothing is written before a "save".
    std::filesystem::path parameter_file;
    /// Asked before 0x1011 "load": the EPOS2 restores only in "Switch on disabled" and NMT
    /// pre-operational (8.2.9), which the device control decides. Empty: always allowed.
    canopen::StoreRestoreOptions restore;
};

/// The object dictionary of a maxon EPOS2 24/5 exactly as chapter 8 of its firmware
/// specification lists it (table 8-67 and sections 8.2.1 - 8.2.131): every object with its
/// type, access, default, value range, persistence and PDO mappability, plus the non-volatile
/// memory behind 0x1010 / 0x1011. The communication objects come from canmaster's services, so a
/// canopen::Node on node_config() runs on this dictionary as it is. The objects' device
/// behaviour (device control, modes, motor) attaches to them through dictionary hooks.
///
/// Neither copyable nor movable: the services' hooks refer to the dictionary.
class Epos2Dictionary {
public:
    explicit Epos2Dictionary(Epos2DictionaryConfig config);
    Epos2Dictionary(const Epos2Dictionary&) = delete;
    Epos2Dictionary& operator=(const Epos2Dictionary&) = delete;

    canopen::ObjectDictionary& objects() { return od_; }
    const canopen::ObjectDictionary& objects() const { return od_; }
    canopen::ParameterStore& store() { return store_; }

    /// What a canopen::Node needs to run on this dictionary: node-ID, the identity of 0x1018
    /// (also its LSS address), and the parameter file, so that the node loads what 0x1010 saved.
    canopen::NodeConfig node_config() const;

private:
    Epos2DictionaryConfig config_;
    canopen::ObjectDictionary od_;
    canopen::ParameterStore store_;
};

/// 0x1018 (8.2.15): maxon's vendor ID; product code = hardware version : application number,
/// revision = software version : application version (high word : low word); the serial number
/// shows the low 32 bits of 0x2004. Also the node's LSS address.
canopen::LssAddress epos2_identity(std::uint64_t serial_number);

/// What the EPOS2's EDS says beyond its objects (CiA 306 [DeviceInfo]): maxon, the EPOS2 24/5,
/// the bit rates of table 8-81, LSS and a granularity of 8 bits.
canopen::DeviceInfo epos2_device_info();

} // namespace eposp::drives::epos2
