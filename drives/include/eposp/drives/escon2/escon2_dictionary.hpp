#pragma once

#include "eposp/canopen/device_info.hpp"
#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/parameter_store.hpp"
#include "eposp/drives/escon2/escon2_hardware.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>

namespace eposp::drives::escon2 {

// ESCON2 FW spec 6.2.7 and table 112: firmware 0x0100, application 0x1000 version 0x0000.
inline constexpr std::uint32_t kMaxonVendorId = 0x0000'00FB;
inline constexpr std::uint16_t kSoftwareVersion = 0x0100;
inline constexpr std::uint16_t kApplicationNumber = 0x1000;
inline constexpr std::uint16_t kApplicationVersion = 0x0000;
/// 6.2.1: CiA 402 (0x0192) servo drive (0x0002).
inline constexpr std::uint32_t kDeviceType = 0x0002'0192;

struct Escon2DictionaryConfig {
    Escon2Hardware hardware = Escon2Hardware::Module60_30;
    std::uint64_t serial_number = 0; ///< 0x2100 sub 1; 0x1018 sub 4 shows its low 32 bits
    /// The non-volatile memory of 0x1010 / 0x1011: nothing is written before a "save".
    std::filesystem::path parameter_file;
    /// Whether the device is in «Power Disable» (the power stage off: Not ready to switch on,
    /// Switch on disabled, Ready to switch on), which many writes and the restore of 6.2.6
    /// require (0x08000022 otherwise). The device control decides; empty: always.
    std::function<bool()> power_disabled;
};

/// The object dictionary of a maxon ESCON2 exactly as chapter 6 of its firmware specification
/// lists it (table 34 and sections 6.2.1 - 6.2.81): every object with its type, access, default,
/// value range, persistence and PDO mapping flag (6.1.4) for the configured hardware, plus the
/// non-volatile memory behind 0x1010 / 0x1011. The ESCON2 has no CAN; the canopen dictionary is
/// its container all the same: reads and writes with the abort codes of table 111 (the USB
/// service interface uses them), store / restore and an EDS export. The device's behaviour
/// attaches to the objects through dictionary hooks and listeners.
///
/// Neither copyable nor movable: the hooks refer to the dictionary.
class Escon2Dictionary {
public:
    explicit Escon2Dictionary(Escon2DictionaryConfig config);
    Escon2Dictionary(const Escon2Dictionary&) = delete;
    Escon2Dictionary& operator=(const Escon2Dictionary&) = delete;

    canopen::ObjectDictionary& objects() { return od_; }
    const canopen::ObjectDictionary& objects() const { return od_; }
    canopen::ParameterStore& store() { return store_; }
    const HardwareData& hardware() const { return hardware_data(config_.hardware); }

    /// Power-up: every value to its default, then the values 0x1010 saved (the report says
    /// whether a store was refused, which the device reports as error 0x6380).
    canopen::StoredValuesReport power_up();

private:
    Escon2DictionaryConfig config_;
    canopen::ObjectDictionary od_;
    canopen::ParameterStore store_;
};

/// 0x1018 (6.2.7): maxon's vendor ID; product code = hardware version : application number,
/// revision = software version : application version (high word : low word); the serial number
/// shows the low 32 bits of 0x2100 sub 1.
canopen::LssAddress escon2_identity(Escon2Hardware hardware, std::uint64_t serial_number);

/// What an ESCON2's EDS says beyond its objects (CiA 306 [DeviceInfo]): maxon, the product, no
/// CAN bit rates, no PDO mapping granularity.
canopen::DeviceInfo escon2_device_info(Escon2Hardware hardware);

} // namespace eposp::drives::escon2
