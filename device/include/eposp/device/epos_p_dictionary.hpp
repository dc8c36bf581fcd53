#pragma once

#include "eposp/canopen/device_info.hpp"
#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/canopen/parameter_store.hpp"
#include "eposp/canopen/store_restore_objects.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace eposp::device {

/// EPOS P firmware specification 11.1 and table 29: the firmware this dictionary follows and the
/// hardware it is (EPOS P 24/5).
inline constexpr std::uint16_t kSoftwareVersion = 0x0110;
inline constexpr std::uint16_t kHardwareVersion = 0x7300;
inline constexpr std::uint16_t kApplicationNumber = 0x0000;
inline constexpr std::uint16_t kApplicationVersion = 0x0000;
/// 10.1: CiA 405, IEC 61131-3 programmable device.
inline constexpr std::uint32_t kDeviceType = 0x0000'0195;

/// 10.36: the axes 0..31 at 0x5280 + n, and table 30's slave numbers.
inline constexpr std::uint16_t kNodeIdIndex = 0x5000;     ///< 10.31: the node-ID on port 2
inline constexpr std::uint16_t kCanBitRateIndex = 0x5001; ///< 10.32: port 2's bit rate code

/// Table 28: the bit rate of a code of 0x5001; empty for the reserved codes and 9 (automatic
/// detection, which on a simulated bus keeps the bus's rate).
std::optional<std::uint32_t> can_bit_rate_of(std::uint16_t code);
/// Table 28: the code of a bit rate; empty for one the table does not list (10 kbit/s).
std::optional<std::uint16_t> can_bit_rate_code(std::uint32_t bit_rate);
inline constexpr std::uint16_t kAxisIndex = 0x5280;
inline constexpr std::uint8_t kAxisCount = 32;
inline constexpr std::uint8_t kInternalSlave = 0; ///< the internal EPOS2 (node 1 on port 1)
inline constexpr std::uint8_t kNoSlave = 255;
/// 10.37, table 31.
inline constexpr std::uint16_t kProgramControlIndex = 0x5F51;
enum class ProgramControl : std::uint16_t {
    Stopped = 0,
    Coldstart = 1,
    Warmstart = 2,
    Hotstart = 3
};

/// CiA 302-3 program download (docs/service-interface.md): the program image (DOMAIN), its
/// control, its identification (the image's CRC-32) and the flash status, each at sub-index 1.
inline constexpr std::uint16_t kProgramDataIndex = 0x1F50;
inline constexpr std::uint16_t kCia302ProgramControlIndex = 0x1F51;
inline constexpr std::uint16_t kProgramIdentificationIndex = 0x1F56;
inline constexpr std::uint16_t kFlashStatusIndex = 0x1F57;
/// CiA 302-3, 0x1F51 written: stop, start, reset (back to the initial values), clear.
enum class ProgramControlCommand : std::uint8_t { Stop = 0, Start = 1, Reset = 2, Clear = 3 };
/// CiA 302-3, 0x1F51 read: the program's state.
enum class ProgramStatus : std::uint8_t { Stopped = 0, Started = 1, NoProgram = 3 };
/// eposp's online access to the PLC's variables by path (docs/service-interface.md): sub 1 the
/// path, sub 2 its value as an IEC literal, sub 3 force, sub 4 unforce.
inline constexpr std::uint16_t kVariableAccessIndex = 0x5F60;

/// Tables 4 and 10: the port codes of the error history and of 0x1016.
inline constexpr std::uint8_t kInternalPort = 1;
inline constexpr std::uint8_t kExternalPort = 2;

/// 10.16 - 10.19: the internal PDOs (0x1500 / 0x1900 ...) follow the 256 numbers of CiA 301's
/// PDO objects: the first is PDO number 257 (canopen::pdo_communication_index).
inline constexpr std::size_t kFirstInternalPdo = 257;

/// 10.20 - 10.29: the network list's sub-index for a slave: 1..127 the node-IDs on port 2, 128
/// the internal EPOS2.
inline constexpr std::uint8_t kInternalSlaveSubIndex = 0x80;

struct EposPDictionaryConfig {
    canopen::NodeId node_id = 1; ///< 0x5000: the controller's node-ID on port 2
    /// 0x5001's default: the code of the bit rate port 2 starts with (1 Mbit/s, code 0, for a
    /// rate table 28 does not list).
    std::uint32_t can_bit_rate = 1'000'000;
    std::uint32_t serial_number = 0; ///< 0x1018 sub 4
    /// The non-volatile memory of 0x1010 / 0x1011: nothing is written before a "save".
    std::filesystem::path parameter_file;
    /// Asked before 0x1011 "load": firmware 0110h refuses it while the program runs.
    canopen::StoreRestoreOptions restore;
    /// 0x1011 sub 2 "eras": deletes the application program, or says why not.
    std::function<canopen::AbortCode()> erase_program;
};

/// The object dictionary of the EPOS P exactly as chapter 10 of its firmware specification
/// lists it (table 32 and sections 10.1 - 10.49): every object with its type, access, default,
/// value range, persistence and PDO mappability, plus the non-volatile memory behind
/// 0x1010 / 0x1011. The objects hold data; the device's behaviour (the manager, the PLC, the
/// process image) attaches to them through dictionary hooks and listeners.
///
/// Neither copyable nor movable: the hooks of 0x1010 / 0x1011 refer to the store.
class EposPDictionary {
public:
    explicit EposPDictionary(EposPDictionaryConfig config);
    EposPDictionary(const EposPDictionary&) = delete;
    EposPDictionary& operator=(const EposPDictionary&) = delete;

    canopen::ObjectDictionary& objects() { return od_; }
    const canopen::ObjectDictionary& objects() const { return od_; }
    canopen::ParameterStore& store() { return store_; }

private:
    EposPDictionaryConfig config_;
    canopen::ObjectDictionary od_;
    canopen::ParameterStore store_;
};

/// 0x1018 (10.13): maxon's vendor ID; product code = hardware version : application number,
/// revision = software version : application version (high word : low word), as on the EPOS2.
canopen::LssAddress epos_p_identity(std::uint32_t serial_number);

/// What the EPOS P's EDS says beyond its objects (CiA 306 [DeviceInfo]): maxon, the EPOS P 24/5,
/// the bit rates of table 28, no LSS, a granularity of 8 bits.
canopen::DeviceInfo epos_p_device_info();

/// The EDS (CiA 306) of the EPOS P as it ships in device/epos-p.eds: the dictionary with its
/// defaults, exported by canopen's export_eds().
std::string epos_p_eds();

} // namespace eposp::device
