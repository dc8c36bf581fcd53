// The EPOS2 dictionary against chapter 8 of the EPOS2 firmware specification, entry by entry.
// The rows are transcribed from the object tables of sections 8.2.1 - 8.2.131 (name, type,
// access, default) with the persistence and PDO-mappability columns of table 8-67, for an
// EPOS2 24/5 where a table gives values per hardware. Where the specification contradicts
// itself, the row says which reading it takes.
#include "eposp/drives/epos2/epos2_dictionary.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace eposp::drives::epos2 {
namespace {

using canopen::Access;
using canopen::DataType;

constexpr auto kI8 = DataType::Integer8;
constexpr auto kI16 = DataType::Integer16;
constexpr auto kI32 = DataType::Integer32;
constexpr auto kU8 = DataType::Unsigned8;
constexpr auto kU16 = DataType::Unsigned16;
constexpr auto kU32 = DataType::Unsigned32;
constexpr auto kU64 = DataType::Unsigned64;
constexpr auto kRO = Access::ReadOnly;
constexpr auto kRW = Access::ReadWrite;
constexpr auto kWO = Access::WriteOnly;
constexpr auto kConst = Access::Const;

/// The default is "–", "depending on hardware" or computed (identity, versions): not compared.
constexpr std::optional<std::int64_t> kAny;

// Flags of a row.
constexpr unsigned kP = 1;      ///< table 8-67 "Subindex of persistent parameters"
constexpr unsigned kPdo = 2;    ///< table 8-67 "PDO mappable parameters"
constexpr unsigned kNodeId = 4; ///< the default is "... + Node ID"

struct SpecEntry {
    std::uint16_t index;
    std::uint8_t sub;
    const char* name;
    DataType type;
    Access access;
    std::optional<std::int64_t> default_value;
    unsigned flags;
};

// clang-format off
const std::vector<SpecEntry> kSpecTable = {
    // 8.2.1 - 8.2.33: communication objects
    {0x1000, 0, "Device Type", kU32, kRO, 0x00020192, 0},
    {0x1001, 0, "Error Register", kU8, kRO, 0, 0},
    {0x1003, 0, "Number of Errors", kU8, kRW, 0, 0},
    {0x1003, 1, "Error History [1]", kU32, kRO, 0, 0},
    {0x1003, 2, "Error History [2]", kU32, kRO, 0, 0},
    {0x1003, 3, "Error History [3]", kU32, kRO, 0, 0},
    {0x1003, 4, "Error History [4]", kU32, kRO, 0, 0},
    {0x1003, 5, "Error History [5]", kU32, kRO, 0, 0},
    {0x1005, 0, "COB-ID SYNC", kU32, kRW, 0x00000080, kP},
    {0x100C, 0, "Guard Time", kU16, kRW, 0, kP},
    {0x100D, 0, "Lifetime Factor", kU8, kRW, 0, kP},
    {0x1010, 1, "Save all Parameters", kU32, kRW, kAny, 0},
    {0x1011, 1, "Restore all Default Parameters", kU32, kRW, kAny, 0},
    {0x1011, 5, "Restore Default PDO COB-IDs", kU32, kRW, kAny, 0},
    {0x1012, 0, "COB-ID Time Stamp Object", kU32, kRW, 0x00000100, kP},
    {0x1013, 0, "High Resolution Time Stamp", kU32, kRW, kAny, kPdo},
    {0x1014, 0, "COB-ID EMCY", kU32, kRW, 0x00000080, kNodeId | kP},
    {0x1016, 1, "Consumer 1 Heartbeat Time", kU32, kRW, 0, kP},
    {0x1016, 2, "Consumer 2 Heartbeat Time", kU32, kRW, 0, kP},
    {0x1017, 0, "Producer Heartbeat Time", kU16, kRW, 0, kP},
    {0x1018, 1, "Vendor ID", kU32, kRO, 0x000000FB, 0},
    {0x1018, 2, "Product Code", kU32, kRO, kAny, 0},
    {0x1018, 3, "Revision Number", kU32, kRO, kAny, 0},
    {0x1018, 4, "Serial Number", kU32, kRO, kAny, 0},
    {0x1020, 1, "Configuration Date", kU32, kRW, 0x00000000, kP},
    {0x1020, 2, "Configuration Time", kU32, kRW, 0x00000000, kP},
    {0x1200, 1, "COB-ID SDO Client to Server", kU32, kRO, 0x00000600, kNodeId},
    {0x1200, 2, "COB-ID SDO Server to Client", kU32, kRO, 0x00000580, kNodeId},
    {0x1400, 1, "COB-ID Receive PDO 1", kU32, kRW, 0x00000200, kNodeId | kP},
    {0x1400, 2, "Transmission Type Receive PDO 1", kU8, kRW, 255, kP},
    {0x1401, 1, "COB-ID Receive PDO 2", kU32, kRW, 0x00000300, kNodeId | kP},
    {0x1401, 2, "Transmission Type Receive PDO 2", kU8, kRW, 255, kP},
    {0x1402, 1, "COB-ID Receive PDO 3", kU32, kRW, 0x00000400, kNodeId | kP},
    {0x1402, 2, "Transmission Type Receive PDO 3", kU8, kRW, 255, kP},
    {0x1403, 1, "COB-ID Receive PDO 4", kU32, kRW, 0x00000500, kNodeId | kP},
    {0x1403, 2, "Transmission Type Receive PDO 4", kU8, kRW, 255, kP},
    // Table 8-67 lists sub-indices 0x01…0x08 of the mappings as persistent; the number of
    // mapped objects is stored with them, or a stored mapping would come back with its default
    // length.
    {0x1600, 0, "Number of mapped Application Objects in Receive PDO", kU8, kRW, 1, kP},
    {0x1600, 1, "1st mapped Object", kU32, kRW, 0x60400010, kP},
    {0x1600, 2, "2nd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1600, 3, "3rd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1600, 4, "4th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1600, 5, "5th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1600, 6, "6th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1600, 7, "7th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1600, 8, "8th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1601, 0, "Number of mapped Application Objects in Receive PDO", kU8, kRW, 2, kP},
    {0x1601, 1, "1st mapped Object", kU32, kRW, 0x60400010, kP},
    {0x1601, 2, "2nd mapped Object", kU32, kRW, 0x60600008, kP},
    {0x1601, 3, "3rd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1601, 4, "4th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1601, 5, "5th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1601, 6, "6th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1601, 7, "7th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1601, 8, "8th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1602, 0, "Number of mapped Application Objects in Receive PDO", kU8, kRW, 2, kP},
    {0x1602, 1, "1st mapped Object", kU32, kRW, 0x60400010, kP},
    {0x1602, 2, "2nd mapped Object", kU32, kRW, 0x607A0020, kP},
    {0x1602, 3, "3rd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1602, 4, "4th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1602, 5, "5th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1602, 6, "6th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1602, 7, "7th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1602, 8, "8th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1603, 0, "Number of mapped Application Objects in Receive PDO", kU8, kRW, 2, kP},
    {0x1603, 1, "1st mapped Object", kU32, kRW, 0x60400010, kP},
    {0x1603, 2, "2nd mapped Object", kU32, kRW, 0x60FF0020, kP},
    {0x1603, 3, "3rd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1603, 4, "4th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1603, 5, "5th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1603, 6, "6th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1603, 7, "7th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1603, 8, "8th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1800, 1, "COB-ID Transmit PDO 1", kU32, kRW, 0x40000180, kNodeId | kP},
    {0x1800, 2, "Transmission Type Transmit PDO 1", kU8, kRW, 255, kP},
    {0x1800, 3, "Inhibit Time Transmit PDO 1", kU16, kRW, 0, kP},
    {0x1801, 1, "COB-ID Transmit PDO 2", kU32, kRW, 0xC0000280, kNodeId | kP},
    {0x1801, 2, "Transmission Type Transmit PDO 2", kU8, kRW, 255, kP},
    {0x1801, 3, "Inhibit Time Transmit PDO 2", kU16, kRW, 0, kP},
    {0x1802, 1, "COB-ID Transmit PDO 3", kU32, kRW, 0xC0000380, kNodeId | kP},
    {0x1802, 2, "Transmission Type Transmit PDO 3", kU8, kRW, 255, kP},
    {0x1802, 3, "Inhibit Time Transmit PDO 3", kU16, kRW, 0, kP},
    {0x1803, 1, "COB-ID Transmit PDO 4", kU32, kRW, 0xC0000480, kNodeId | kP},
    {0x1803, 2, "Transmission Type Transmit PDO 4", kU8, kRW, 253, kP},
    {0x1803, 3, "Inhibit Time Transmit PDO 4", kU16, kRW, 0, kP},
    {0x1A00, 0, "Number of mapped Application Objects in Transmit PDO", kU8, kRW, 1, kP},
    {0x1A00, 1, "1st mapped Object", kU32, kRW, 0x60410010, kP},
    {0x1A00, 2, "2nd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A00, 3, "3rd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A00, 4, "4th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A00, 5, "5th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A00, 6, "6th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A00, 7, "7th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A00, 8, "8th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A01, 0, "Number of mapped Application Objects in Transmit PDO", kU8, kRW, 2, kP},
    {0x1A01, 1, "1st mapped Object", kU32, kRW, 0x60410010, kP},
    {0x1A01, 2, "2nd mapped Object", kU32, kRW, 0x60610008, kP},
    {0x1A01, 3, "3rd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A01, 4, "4th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A01, 5, "5th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A01, 6, "6th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A01, 7, "7th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A01, 8, "8th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A02, 0, "Number of mapped Application Objects in Transmit PDO", kU8, kRW, 2, kP},
    {0x1A02, 1, "1st mapped Object", kU32, kRW, 0x60410010, kP},
    // 8.2.32 prints "0x6064020": position actual value, 32 bits.
    {0x1A02, 2, "2nd mapped Object", kU32, kRW, 0x60640020, kP},
    {0x1A02, 3, "3rd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A02, 4, "4th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A02, 5, "5th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A02, 6, "6th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A02, 7, "7th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A02, 8, "8th mapped Object", kU32, kRW, 0x00000000, kP},
    // 8.2.33 prints sub-index "0x08" for the number of mapped objects.
    {0x1A03, 0, "Number of mapped Application Objects in Transmit PDO", kU8, kRW, 2, kP},
    {0x1A03, 1, "1st mapped Object", kU32, kRW, 0x60410010, kP},
    {0x1A03, 2, "2nd mapped Object", kU32, kRW, 0x606C0020, kP},
    {0x1A03, 3, "3rd mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A03, 4, "4th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A03, 5, "5th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A03, 6, "6th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A03, 7, "7th mapped Object", kU32, kRW, 0x00000000, kP},
    {0x1A03, 8, "8th mapped Object", kU32, kRW, 0x00000000, kP},
    // 8.2.34 - 8.2.83: manufacturer objects
    {0x2000, 0, "Node ID", kU8, kRW, 0, kNodeId | kP},
    {0x2001, 0, "CAN Bitrate", kU16, kRW, 9, kP},
    {0x2002, 0, "RS232 Baudrate", kU16, kRW, 5, kP},
    {0x2003, 1, "Software Version", kU16, kRO, kAny, 0},
    {0x2003, 2, "Hardware Version", kU16, kRO, kAny, 0},
    {0x2003, 3, "Application Number", kU16, kRO, kAny, 0},
    {0x2003, 4, "Application Version", kU16, kRO, kAny, 0},
    {0x2003, 5, "Internal Object", kU16, kRO, kAny, 0},
    {0x2004, 0, "Serial Number", kU64, kConst, kAny, 0},
    {0x2005, 0, "RS232 Frame Timeout", kU16, kRW, 500, kP},
    {0x2006, 0, "USB Frame Timeout", kU16, kRW, 500, kP},
    {0x2008, 0, "Miscellaneous Configuration", kU16, kRW, 0x0000, kP},
    {0x200A, 0, "CAN Bitrate Display", kU16, kRO, kAny, 0},
    {0x200C, 1, "Custom Persistent Memory 1", kU32, kRW, 0x0000, kP},
    {0x200C, 2, "Custom Persistent Memory 2", kU32, kRW, 0x0000, kP},
    {0x200C, 3, "Custom Persistent Memory 3", kU32, kRW, 0x0000, kP},
    {0x200C, 4, "Custom Persistent Memory 4", kU32, kRW, 0x0000, kP},
    {0x2020, 0, "Incremental Encoder 1 Counter", kU32, kRO, kAny, kPdo},
    {0x2021, 0, "Incremental Encoder 1 Counter at Index Pulse", kU32, kRO, kAny, kPdo},
    // Table 8-67 types 0x2022 UNSIGNED32 and 0x2031 INTEGER16; sections 8.2.46 / 8.2.51 win.
    {0x2022, 0, "Hall Sensor Pattern", kU16, kRO, kAny, kPdo},
    {0x2027, 0, "Current Actual Value Averaged", kI16, kRO, kAny, kPdo},
    {0x2028, 0, "Velocity Actual Value Averaged", kI32, kRO, kAny, kPdo},
    {0x2029, 0, "Auxiliary Velocity Actual Value Averaged", kI32, kRO, kAny, kPdo},
    {0x2030, 0, "Current Mode Setting Value", kI16, kRW, 0, kPdo},
    {0x2031, 0, "Current Demand Value", kI32, kRO, kAny, kPdo},
    {0x2062, 0, "Position Mode Setting Value", kI32, kRW, 0, kPdo},
    {0x2069, 0, "Auxiliary Velocity Sensor Actual Value", kI32, kRO, kAny, 0},
    {0x206B, 0, "Velocity Mode Setting Value", kI32, kRW, kAny, kPdo},
    {0x206C, 0, "Auxiliary Velocity Actual Value", kI32, kRO, kAny, 0},
    {0x2070, 1, "Configuration of Digital Input 1", kU16, kRW, 15, kP},
    {0x2070, 2, "Configuration of Digital Input 2", kU16, kRW, 14, kP},
    {0x2070, 3, "Configuration of Digital Input 3", kU16, kRW, 13, kP},
    {0x2070, 4, "Configuration of Digital Input 4", kU16, kRW, 2, kP},
    {0x2070, 5, "Configuration of Digital Input 5", kU16, kRW, 1, kP},
    {0x2070, 6, "Configuration of Digital Input 6", kU16, kRW, 0, kP},
    {0x2071, 1, "Digital Input Functionalities State", kU16, kRO, kAny, kPdo},
    {0x2071, 2, "Digital Input Functionalities Mask", kU16, kRW, 0xE007, kP},
    {0x2071, 3, "Digital Input Functionalities Polarity", kU16, kRW, 0x0000, kP},
    {0x2071, 4, "Digital Input Functionalities Execution Mask", kU16, kRW, 0x0008, kP},
    {0x2074, 1, "Position Marker captured Position", kI32, kRO, kAny, kPdo},
    {0x2074, 2, "Position Marker Edge Type", kU8, kRW, 0, kP},
    {0x2074, 3, "Position Marker Mode", kU8, kRW, 1, kP},
    {0x2074, 4, "Position Marker Counter", kU16, kRW, 0, kPdo},
    {0x2074, 5, "Position Marker History [1]", kI32, kRO, kAny, 0},
    {0x2074, 6, "Position Marker History [2]", kI32, kRO, kAny, 0},
    {0x2078, 1, "Digital Output Functionalities State", kU16, kRW, kAny, kPdo},
    {0x2078, 2, "Digital Output Functionalities Mask", kU16, kRW, 0x0000, kP},
    {0x2078, 3, "Digital Output Functionalities Polarity", kU16, kRW, 0x0000, kP},
    {0x2079, 1, "Configuration of Digital Output 1", kU16, kRW, 15, kP},
    {0x2079, 2, "Configuration of Digital Output 2", kU16, kRW, 14, kP},
    {0x2079, 3, "Configuration of Digital Output 3", kU16, kRW, 13, kP},
    {0x2079, 4, "Configuration of Digital Output 4", kU16, kRW, 12, kP},
    {0x207A, 1, "Position Compare Configuration", kU16, kRW, 0, kPdo},
    {0x207A, 2, "Position Compare Reference Position", kI32, kRW, 0, kPdo},
    {0x207A, 3, "Position Compare Interval Width", kI32, kRW, 0, kP},
    {0x207A, 4, "Position Compare Interval Repetitions", kU16, kRW, 0, kP},
    {0x207A, 5, "Position Compare Pulse Width", kU16, kRW, 0, kP},
    {0x207B, 1, "Configuration of Analog Input 1", kU16, kRW, 15, kP},
    {0x207B, 2, "Configuration of Analog Input 2", kU16, kRW, 14, kP},
    {0x207C, 1, "Analog Input 1", kI16, kRO, kAny, kPdo},
    {0x207C, 2, "Analog Input 2", kI16, kRO, kAny, kPdo},
    {0x207D, 0, "Analog Input Functionalities Execution Mask", kU16, kRW, 0, kP},
    {0x207E, 0, "Analog Output 1", kU16, kRW, 0, kPdo},
    {0x2080, 0, "Current Threshold for Homing Mode", kU16, kRW, 500, kP | kPdo},
    // Table 8-67 types 0x2081 UNSIGNED32; 8.2.67 gives INTEGER32 with a signed range.
    {0x2081, 0, "Home Position", kI32, kRW, 0, kP | kPdo},
    {0x2082, 0, "Home Position Displacement", kI32, kRO, kAny, 0},
    // 8.2.69: a 64-bit structure (type 0x0040), held as UNSIGNED64.
    {0x20C1, 0, "Interpolation Data Record", kU64, kWO, kAny, kPdo},
    {0x20C4, 1, "Interpolation Buffer Status", kU16, kRO, kAny, kPdo},
    {0x20C4, 2, "Interpolation Buffer Underflow Warning", kU16, kRW, 4, kP},
    {0x20C4, 3, "Interpolation Buffer Overflow Warning", kU16, kRW, 60, kP},
    {0x20F4, 0, "Following Error Actual Value", kI16, kRO, kAny, kPdo},
    {0x2100, 1, "Brake Reaction Rise Time", kU16, kRW, 10, kP},
    {0x2100, 2, "Brake Reaction Fall Time", kU16, kRW, 10, kP},
    {0x2100, 3, "Brake Timeout", kU16, kRW, 65535, kP},
    {0x2101, 1, "Standstill Window", kU16, kRW, 30, kP},
    {0x2101, 2, "Standstill Window Time", kU16, kRW, 50, kP},
    {0x2101, 3, "Standstill Timeout", kU16, kRW, 1000, kP},
    {0x2210, 1, "Pulse Number Incremental Encoder 1", kU32, kRW, 500, kP},
    {0x2210, 2, "Position Sensor Type", kU16, kRW, 0x01, kP},
    {0x2210, 4, "Position Sensor Polarity", kU16, kRW, 0x00, kP},
    {0x2211, 1, "SSI Encoder Datarate", kU16, kRW, 500, kP},
    {0x2211, 2, "SSI Encoder Number of Data Bits", kU16, kRW, 3085, kP},
    {0x2211, 3, "SSI Encoder Actual Position", kI32, kRO, kAny, 0},
    {0x2211, 4, "SSI Encoding Type", kU16, kRW, 0, kP},
    {0x2212, 1, "Incremental Encoder 2 Pulse Number", kU32, kRW, 500, kP},
    {0x2212, 2, "Incremental Encoder 2 Counter", kU32, kRO, kAny, kPdo},
    {0x2212, 3, "Incremental Encoder 2 Counter at Index Pulse", kU32, kRO, kAny, kPdo},
    {0x2213, 1, "Sinus Incremental Encoder 2 Resolution", kU32, kRW, 0x00800006, kP},
    {0x2213, 2, "Sinus Incremental Encoder 2 Actual Position", kI32, kRO, kAny, 0},
    {0x2220, 0, "Controller Structure", kU16, kRW, kAny, kP},
    {0x2230, 1, "Gear Ratio Numerator", kU32, kRW, 0, kP},
    {0x2230, 2, "Gear Ratio Denominator", kU16, kRW, 1, kP},
    {0x2230, 3, "Gear Maximal Speed", kU32, kRW, 100000, kP},
    {0x2300, 1, "Digital Position Desired Value", kI32, kRO, 0, 0},
    {0x2300, 2, "Digital Position Scaling Numerator", kU16, kRW, 1, kP},
    {0x2300, 3, "Digital Position Scaling Denominator", kU16, kRW, 1, kP},
    {0x2300, 4, "Digital Position Polarity", kU8, kRW, 0, kP},
    {0x2300, 5, "Digital Position Offset", kI32, kRW, 0, kP},
    {0x2301, 1, "Analog Current Setpoint Scaling", kI16, kRW, 0, kP},
    {0x2301, 2, "Analog Current Setpoint Offset", kI16, kRW, 0, kP},
    {0x2301, 3, "Analog Current Setpoint Notation Index", kI8, kRW, 0, kP},
    {0x2301, 4, "Analog Current Setpoint", kI16, kRO, kAny, 0},
    {0x2302, 1, "Analog Velocity Setpoint Scaling", kI16, kRW, 0, kP},
    {0x2302, 2, "Analog Velocity Setpoint Offset", kI32, kRW, 0, kP},
    {0x2302, 3, "Analog Velocity Setpoint Notation Index", kI8, kRW, 0, kP},
    {0x2302, 4, "Analog Velocity Setpoint", kI32, kRO, kAny, 0},
    {0x2303, 1, "Analog Position Setpoint Scaling", kI16, kRW, 0, kP},
    {0x2303, 2, "Analog Position Setpoint Offset", kI32, kRW, 0, kP},
    {0x2303, 3, "Analog Position Setpoint Notation Index", kI8, kRW, 0, kP},
    {0x2303, 4, "Analog Position Setpoint", kI32, kRO, kAny, 0},
    // 8.2.84 - 8.2.131: profile objects
    {0x6007, 0, "Abort Connection Option Code", kI16, kRW, 3, kP},
    {0x6040, 0, "Controlword", kU16, kRW, kAny, kPdo},
    {0x6041, 0, "Statusword", kU16, kRO, kAny, kPdo},
    {0x605B, 0, "Shutdown Option Code", kI16, kRW, 0, kP},
    {0x605C, 0, "Disable Operation Option Code", kI16, kRW, 1, kP},
    {0x605E, 0, "Fault Reaction Option Code", kI16, kRW, 2, kP},
    {0x6060, 0, "Modes of Operation", kI8, kRW, 1, kPdo},
    {0x6061, 0, "Modes of Operation Display", kI8, kRO, 1, kPdo},
    {0x6062, 0, "Position Demand Value", kI32, kRO, 0, kPdo},
    {0x6064, 0, "Position Actual Value", kI32, kRO, kAny, kPdo},
    {0x6065, 0, "Maximal Following Error", kU32, kRW, 2000, kP | kPdo},
    {0x6067, 0, "Position Window", kU32, kRW, 4294967295, kP},
    {0x6068, 0, "Position Window Time", kU16, kRW, 0, kP},
    {0x6069, 0, "Velocity Sensor Actual Value", kI32, kRO, kAny, kPdo},
    {0x606B, 0, "Velocity Demand Value", kI32, kRO, kAny, kPdo},
    {0x606C, 0, "Velocity Actual Value", kI32, kRO, kAny, kPdo},
    {0x606D, 0, "Velocity Window", kU32, kRW, 4294967295, kP},
    {0x606E, 0, "Velocity Window Time", kU16, kRW, 0, kP},
    {0x6078, 0, "Current Actual Value", kI16, kRO, kAny, kPdo},
    {0x607A, 0, "Target Position", kI32, kRW, 0, kPdo},
    {0x607C, 0, "Home Offset", kI32, kRW, 0, kP | kPdo},
    {0x607D, 1, "Minimal Position Limit", kI32, kRW, -2147483648, kP},
    {0x607D, 2, "Maximal Position Limit", kI32, kRW, 2147483647, kP},
    {0x607F, 0, "Maximal Profile Velocity", kU32, kRW, 25000, kP},
    {0x6081, 0, "Profile Velocity", kU32, kRW, 1000, kP | kPdo},
    {0x6083, 0, "Profile Acceleration", kU32, kRW, 10000, kP | kPdo},
    {0x6084, 0, "Profile Deceleration", kU32, kRW, 10000, kP | kPdo},
    {0x6085, 0, "Quickstop Deceleration", kU32, kRW, 10000, kP | kPdo},
    {0x6086, 0, "Motion Profile Type", kI16, kRW, 0, kP | kPdo},
    {0x6089, 0, "Position Notation Index", kI8, kRW, 0x00, kP},
    {0x608A, 0, "Position Dimension Index", kU8, kRW, 0xAC, kP},
    {0x608B, 0, "Velocity Notation Index", kI8, kRW, 0, kP},
    {0x608C, 0, "Velocity Dimension Index", kU8, kRW, 0xA4, kP},
    {0x608D, 0, "Acceleration Notation Index", kI8, kRW, 0x00, kP},
    {0x608E, 0, "Acceleration Dimension Index", kU8, kRW, 0xA4, kP},
    {0x6098, 0, "Homing Method", kI8, kRW, 7, kP | kPdo},
    {0x6099, 1, "Speed for Switch Search", kU32, kRW, 100, kP | kPdo},
    {0x6099, 2, "Speed for Zero Search", kU32, kRW, 10, kP | kPdo},
    {0x609A, 0, "Homing Acceleration", kU32, kRW, 1000, kP | kPdo},
    {0x60C0, 0, "Interpolation Sub Mode Selection", kI16, kRW, -1, 0},
    {0x60C2, 1, "Interpolation Time Period Value", kU8, kRW, 1, 0},
    // 8.2.122 prints sub-index 0x01 twice; the time index is sub-index 2.
    {0x60C2, 2, "Interpolation Time Index", kI8, kRW, -3, 0},
    {0x60C4, 1, "Maximum Buffer Size", kU32, kRO, kAny, 0},
    {0x60C4, 2, "Actual Buffer Size", kU32, kRO, kAny, kPdo},
    {0x60C4, 3, "Buffer Organization", kU8, kRW, 0, 0},
    {0x60C4, 4, "Buffer Position", kU16, kRW, 0, 0},
    {0x60C4, 5, "Size of Data Record", kU8, kWO, kAny, 0},
    {0x60C4, 6, "Buffer Clear", kU8, kWO, 0, kPdo},
    {0x60C5, 0, "Max Acceleration", kU32, kRW, 4294967295, kP},
    {0x60F6, 1, "Current Regulator P-Gain", kI16, kRW, kAny, kP | kPdo},
    {0x60F6, 2, "Current Regulator I-Gain", kI16, kRW, kAny, kP | kPdo},
    {0x60F9, 1, "Velocity Regulator P-Gain", kI16, kRW, kAny, kP | kPdo},
    {0x60F9, 2, "Velocity Regulator I-Gain", kI16, kRW, kAny, kP | kPdo},
    // 8.2.126 types the feed-forward factors INTEGER16 with the range 0 ... 65 535 of an
    // UNSIGNED16, which 0x60FB sub 4 / 5 have.
    {0x60F9, 4, "Velocity Feedforward Factor in Speed Regulator", kU16, kRW, 0, kP | kPdo},
    {0x60F9, 5, "Acceleration Feedforward Factor in Speed Regulator", kU16, kRW, 0, kP | kPdo},
    {0x60FB, 1, "Position Regulator P-Gain", kI16, kRW, kAny, kP | kPdo},
    {0x60FB, 2, "Position Regulator I-Gain", kI16, kRW, kAny, kP | kPdo},
    {0x60FB, 3, "Position Regulator D-Gain", kI16, kRW, kAny, kP | kPdo},
    {0x60FB, 4, "Velocity Feed Forward Factor", kU16, kRW, 0, kP | kPdo},
    {0x60FB, 5, "Acceleration Feed Forward Factor", kU16, kRW, 0, kP | kPdo},
    {0x60FF, 0, "Target Velocity", kI32, kRW, kAny, kPdo},
    {0x6402, 0, "Motor Type", kU16, kRW, 10, kP},
    {0x6410, 1, "Continuous Current Limit", kU16, kRW, 5000, kP | kPdo},
    {0x6410, 2, "Output Current Limit", kU16, kRW, 10000, kP | kPdo},
    {0x6410, 3, "Pole Pair Number", kU8, kRW, 1, kP},
    {0x6410, 4, "Maximal Motor Speed", kU32, kRW, 25000, kP | kPdo},
    {0x6410, 5, "Thermal Time Constant Winding", kU16, kRW, 40, kP},
    {0x6502, 0, "Supported Drive Modes", kU32, kConst, 0x003F0065, 0},
};
// clang-format on

/// Every object of table 8-67 with its object code (0x20C1 "STRUCT" is one VAR).
constexpr auto kVar = canopen::ObjectCode::Var;
constexpr auto kArray = canopen::ObjectCode::Array;
constexpr auto kRecord = canopen::ObjectCode::Record;
// clang-format off
const std::vector<std::pair<std::uint16_t, canopen::ObjectCode>> kObjectOverview = {
    {0x1000, kVar}, {0x1001, kVar}, {0x1003, kArray}, {0x1005, kVar}, {0x1008, kVar},
    {0x100C, kVar}, {0x100D, kVar}, {0x1010, kArray}, {0x1011, kArray}, {0x1012, kVar},
    {0x1013, kVar}, {0x1014, kVar}, {0x1016, kArray}, {0x1017, kVar}, {0x1018, kRecord},
    {0x1020, kArray}, {0x1200, kRecord}, {0x1400, kRecord}, {0x1401, kRecord}, {0x1402, kRecord},
    {0x1403, kRecord}, {0x1600, kRecord}, {0x1601, kRecord}, {0x1602, kRecord}, {0x1603, kRecord},
    {0x1800, kRecord}, {0x1801, kRecord}, {0x1802, kRecord}, {0x1803, kRecord}, {0x1A00, kRecord},
    {0x1A01, kRecord}, {0x1A02, kRecord}, {0x1A03, kRecord}, {0x2000, kVar}, {0x2001, kVar},
    {0x2002, kVar}, {0x2003, kRecord}, {0x2004, kVar}, {0x2005, kVar}, {0x2006, kVar},
    {0x2008, kVar}, {0x200A, kVar}, {0x200C, kRecord}, {0x2020, kVar}, {0x2021, kVar},
    {0x2022, kVar}, {0x2027, kVar}, {0x2028, kVar}, {0x2029, kVar}, {0x2030, kVar}, {0x2031, kVar},
    {0x2062, kVar}, {0x2069, kVar}, {0x206B, kVar}, {0x206C, kVar}, {0x2070, kRecord},
    {0x2071, kRecord}, {0x2074, kRecord}, {0x2078, kRecord}, {0x2079, kRecord}, {0x207A, kRecord},
    {0x207B, kArray}, {0x207C, kRecord}, {0x207D, kVar}, {0x207E, kVar}, {0x2080, kVar},
    {0x2081, kVar}, {0x2082, kVar}, {0x20C1, kVar}, {0x20C4, kRecord}, {0x20F4, kVar},
    {0x2100, kRecord}, {0x2101, kRecord}, {0x2210, kRecord}, {0x2211, kRecord}, {0x2212, kRecord},
    {0x2213, kRecord}, {0x2220, kVar}, {0x2230, kRecord}, {0x2300, kRecord}, {0x2301, kRecord},
    {0x2302, kRecord}, {0x2303, kRecord}, {0x6007, kVar}, {0x6040, kVar}, {0x6041, kVar},
    {0x605B, kVar}, {0x605C, kVar}, {0x605E, kVar}, {0x6060, kVar}, {0x6061, kVar}, {0x6062, kVar},
    {0x6064, kVar}, {0x6065, kVar}, {0x6067, kVar}, {0x6068, kVar}, {0x6069, kVar}, {0x606B, kVar},
    {0x606C, kVar}, {0x606D, kVar}, {0x606E, kVar}, {0x6078, kVar}, {0x607A, kVar}, {0x607C, kVar},
    {0x607D, kArray}, {0x607F, kVar}, {0x6081, kVar}, {0x6083, kVar}, {0x6084, kVar},
    {0x6085, kVar}, {0x6086, kVar}, {0x6089, kVar}, {0x608A, kVar}, {0x608B, kVar}, {0x608C, kVar},
    {0x608D, kVar}, {0x608E, kVar}, {0x6098, kVar}, {0x6099, kArray}, {0x609A, kVar},
    {0x60C0, kVar}, {0x60C2, kRecord}, {0x60C4, kRecord}, {0x60C5, kVar}, {0x60F6, kRecord},
    {0x60F9, kRecord}, {0x60FB, kRecord}, {0x60FF, kVar}, {0x6402, kVar}, {0x6410, kRecord},
    {0x6502, kVar},
};
// clang-format on

/// The static value ranges of the sections' "Value Range" rows, for the entries a master may
/// write. Ranges that span the whole type are left out: nothing is outside them.
struct SpecRange {
    std::uint16_t index;
    std::uint8_t sub;
    std::int64_t low;
    std::int64_t high;
};
// clang-format off
const std::vector<SpecRange> kSpecRanges = {
    {0x1005, 0, 0x80, 0x80}, // printed "80 80": the COB-ID 0x80
    {0x1012, 0, 0x100, 0x100},
    {0x2000, 0, 1, 127}, {0x2002, 0, 0, 5},
    {0x2070, 1, 0, 15}, {0x2070, 2, 0, 15}, {0x2070, 3, 0, 15}, {0x2070, 4, 0, 15},
    {0x2070, 5, 0, 15}, {0x2070, 6, 0, 15},
    {0x2074, 3, 0, 3},
    {0x2079, 1, 0, 15}, {0x2079, 2, 0, 15}, {0x2079, 3, 0, 15}, {0x2079, 4, 0, 15},
    {0x207A, 3, 0, 2'147'483'647}, {0x207E, 0, 0, 10'000},
    {0x20C4, 2, 0, 63}, {0x20C4, 3, 1, 64},
    {0x2210, 1, 16, 2'500'000}, {0x2211, 1, 400, 2000}, {0x2212, 1, 16, 2'500'000},
    {0x2230, 2, 1, 65'535}, {0x2230, 3, 1, 4'294'967'295},
    {0x2300, 4, 0, 1}, {0x2301, 3, -2, 0}, {0x2302, 3, -2, 0}, {0x2303, 3, -2, 0},
    {0x6007, 0, 1, 3}, {0x605B, 0, 0, 1}, {0x605C, 0, 0, 1}, {0x605E, 0, -1, 2},
    {0x6067, 0, 0, 2'147'483'647},
    {0x607F, 0, 1, 25'000}, // table 8-119: 0x6410 sub 4 at its default, no gear
    {0x6083, 0, 1, 4'294'967'295}, {0x6084, 0, 1, 4'294'967'295},
    {0x6085, 0, 1, 4'294'967'295},
    {0x6089, 0, 0, 0}, {0x608A, 0, 0xAC, 0xAC}, {0x608B, 0, -3, 0}, {0x608C, 0, 0xA4, 0xA4},
    {0x608D, 0, 0, 0}, {0x608E, 0, 0xA4, 0xA4},
    {0x60C0, 0, -1, -1}, {0x60C2, 1, 1, 1}, {0x60C2, 2, -3, -3},
    {0x60C4, 3, 0, 0}, {0x60C4, 4, 0, 64}, {0x60C4, 5, 8, 8}, {0x60C4, 6, 0, 1},
    {0x60C5, 0, 1, 4'294'967'295},
    {0x60F6, 1, 0, 32'767}, {0x60F6, 2, 0, 32'767},
    {0x60F9, 1, 0, 32'767}, {0x60F9, 2, 0, 32'767},
    {0x60FB, 1, 0, 32'767}, {0x60FB, 2, 0, 32'767}, {0x60FB, 3, 0, 32'767},
    {0x6410, 1, 0, 5000}, {0x6410, 2, 0, 10'000}, {0x6410, 3, 1, 255},
    {0x6410, 4, 1, 4'294'967'295}, {0x6410, 5, 1, 5400},
};
// clang-format on

/// Value ranges bounded by another entry ("1 ... Maximal Profile Velocity"); `symmetric` for
/// "-Maximal profile velocity ... Maximal profile velocity".
struct BoundedRange {
    std::uint16_t index;
    std::uint8_t sub;
    std::uint16_t bound_index;
    std::uint8_t bound_sub;
    bool symmetric;
};
const std::vector<BoundedRange> kBoundedRanges = {
    {0x2030, 0, 0x6410, 2, true},  // 8.2.50: output current limit
    {0x206B, 0, 0x607F, 0, true},  // 8.2.54
    {0x2302, 2, 0x607F, 0, true},  // 8.2.82
    {0x6081, 0, 0x607F, 0, false}, // 8.2.107
    {0x6083, 0, 0x60C5, 0, false}, // 8.2.108: max acceleration
    {0x6084, 0, 0x60C5, 0, false}, // 8.2.109
    {0x6085, 0, 0x60C5, 0, false}, // 8.2.110
    {0x6099, 1, 0x607F, 0, false}, // 8.2.119
    {0x6099, 2, 0x607F, 0, false}, // 8.2.119
    {0x609A, 0, 0x60C5, 0, false}, // 8.2.120
    {0x60FF, 0, 0x607F, 0, true},  // 8.2.128
};

/// Value ranges given as a list of codes (a table of chapter 8).
struct ValueList {
    std::uint16_t index;
    std::uint8_t sub;
    std::vector<std::int64_t> values;
};
const std::vector<ValueList> kValueLists = {
    {0x2001, 0, {0, 1, 2, 3, 4, 6, 7, 9}},                // table 8-81
    {0x207B, 1, {0, 1, 2, 8, 9, 10, 11, 12, 13, 14, 15}}, // table 8-97
    {0x207B, 2, {0, 1, 2, 8, 9, 10, 11, 12, 13, 14, 15}},
    {0x2211, 4, {0, 1}},                                                       // table 8-106
    {0x2220, 0, {0, 1}},                                                       // table 8-108
    {0x6060, 0, {7, 6, 3, 1, -1, -2, -3, -4, -5, -6}},                         // table 8-118
    {0x6086, 0, {0, 1}},                                                       // table 8-120
    {0x6098, 0, {35, 34, 33, 27, 23, 18, 17, 11, 7, 2, 1, 0, -1, -2, -3, -4}}, // table 8-121
    {0x6402, 0, {1, 10, 11}}, // table 8-125 for an EPOS2 24/5
};

constexpr canopen::NodeId kNode = 5;

std::int64_t as_integer(DataType type, const canopen::Bytes& bytes) {
    switch (type) {
    case kI8:
        return canopen::decode<std::int8_t>(bytes);
    case kI16:
        return canopen::decode<std::int16_t>(bytes);
    case kI32:
        return canopen::decode<std::int32_t>(bytes);
    case kU8:
        return canopen::decode<std::uint8_t>(bytes);
    case kU16:
        return canopen::decode<std::uint16_t>(bytes);
    case kU32:
        return canopen::decode<std::uint32_t>(bytes);
    case kU64:
        return static_cast<std::int64_t>(canopen::decode<std::uint64_t>(bytes));
    default:
        throw std::invalid_argument("as_integer: not a type of table 8-68");
    }
}

/// The bytes of `value` as `type`, or nullopt when the type cannot hold it.
std::optional<canopen::Bytes> bytes_of(DataType type, std::int64_t value) {
    const auto fits = [value]<typename T>(T) {
        return std::in_range<T>(value) ? std::optional(canopen::encode(static_cast<T>(value)))
                                       : std::nullopt;
    };
    switch (type) {
    case kI8:
        return fits(std::int8_t{});
    case kI16:
        return fits(std::int16_t{});
    case kI32:
        return fits(std::int32_t{});
    case kU8:
        return fits(std::uint8_t{});
    case kU16:
        return fits(std::uint16_t{});
    case kU32:
        return fits(std::uint32_t{});
    default:
        throw std::invalid_argument("bytes_of: not a type with a range here");
    }
}

std::string entry_name(std::uint16_t index, std::uint8_t sub) {
    return fmt::format("0x{:04X} sub {}", index, sub);
}

class Epos2ObjectTable : public ::testing::Test {
protected:
    static Epos2DictionaryConfig config() {
        Epos2DictionaryConfig config;
        config.node_id = kNode;
        config.serial_number = 0x0000'0012'3456'789A;
        config.parameter_file = "never-written.bin";
        return config;
    }

    Epos2Dictionary dictionary{config()};
    canopen::ObjectDictionary& od = dictionary.objects();
};

TEST_F(Epos2ObjectTable, EveryEntryHasTheSpecifiedNameTypeAccessDefaultAndAttributes) {
    for (const SpecEntry& row : kSpecTable) {
        SCOPED_TRACE(entry_name(row.index, row.sub) + ": " + row.name);
        const canopen::SubObject* sub = od.find(row.index, row.sub);
        if (sub == nullptr) {
            ADD_FAILURE() << "missing";
            continue;
        }
        EXPECT_EQ(sub->name, row.name);
        EXPECT_EQ(sub->type, row.type);
        // Table 8-77: the read-write objects PDOs may map are receive PDO objects, rww (CiA 306).
        const bool output = row.access == kRW && (row.flags & kPdo) != 0;
        EXPECT_EQ(sub->access, output ? Access::ReadWriteOutput : row.access);
        EXPECT_EQ(sub->persistent, (row.flags & kP) != 0);
        EXPECT_EQ(sub->pdo_mappable, (row.flags & kPdo) != 0);
        if (row.default_value) {
            const std::int64_t node_part = (row.flags & kNodeId) != 0 ? kNode : 0;
            EXPECT_EQ(as_integer(row.type, sub->default_value), *row.default_value + node_part);
            EXPECT_EQ(sub->value, sub->default_value);
        }
    }
}

TEST_F(Epos2ObjectTable, HasNoEntryTheSpecificationDoesNotList) {
    std::set<std::pair<std::uint16_t, std::uint8_t>> listed = {{0x1008, 0}};
    for (const SpecEntry& row : kSpecTable) {
        listed.emplace(row.index, row.sub);
    }
    for (const auto& [index, object] : od.objects()) {
        for (const auto& [sub_index, sub] : object.subs) {
            const bool number_of_entries = object.code != kVar && sub_index == 0;
            EXPECT_TRUE(listed.contains({index, sub_index}) || number_of_entries)
                << entry_name(index, sub_index) << " " << sub.name;
        }
    }
}

TEST_F(Epos2ObjectTable, HasExactlyTheObjectsOfTable8_67) {
    std::set<std::uint16_t> overview;
    for (const auto& [index, code] : kObjectOverview) {
        overview.insert(index);
        const canopen::Object* object = od.find(index);
        ASSERT_NE(object, nullptr) << fmt::format("0x{:04X}", index);
        EXPECT_EQ(object->code, code) << fmt::format("0x{:04X}", index);
    }
    for (const auto& [index, object] : od.objects()) {
        EXPECT_TRUE(overview.contains(index)) << fmt::format("0x{:04X} {}", index, object.name);
    }
}

TEST_F(Epos2ObjectTable, WritesInsideTheValueRangeAreAcceptedAndOutsideRefused) {
    for (const SpecRange& range : kSpecRanges) {
        SCOPED_TRACE(entry_name(range.index, range.sub));
        const DataType type = od.find(range.index, range.sub)->type;
        EXPECT_EQ(od.write(range.index, range.sub, *bytes_of(type, range.low)),
                  canopen::AbortCode::None);
        EXPECT_EQ(od.write(range.index, range.sub, *bytes_of(type, range.high)),
                  canopen::AbortCode::None);
        if (const auto below = bytes_of(type, range.low - 1)) {
            EXPECT_EQ(od.write(range.index, range.sub, *below), canopen::AbortCode::ValueTooLow);
        }
        if (const auto above = bytes_of(type, range.high + 1)) {
            EXPECT_EQ(od.write(range.index, range.sub, *above), canopen::AbortCode::ValueTooHigh);
        }
    }
}

TEST_F(Epos2ObjectTable, WritesBeyondTheBoundingObjectAreRefused) {
    constexpr std::int64_t kBound = 1000;
    for (const BoundedRange& range : kBoundedRanges) {
        SCOPED_TRACE(entry_name(range.index, range.sub));
        const DataType bound_type = od.find(range.bound_index, range.bound_sub)->type;
        ASSERT_EQ(od.write(range.bound_index, range.bound_sub, *bytes_of(bound_type, kBound)),
                  canopen::AbortCode::None);
        const DataType type = od.find(range.index, range.sub)->type;
        const auto write = [&](std::int64_t value) {
            return od.write(range.index, range.sub, *bytes_of(type, value));
        };
        EXPECT_EQ(write(kBound), canopen::AbortCode::None);
        EXPECT_EQ(write(kBound + 1), canopen::AbortCode::ValueTooHigh);
        if (range.symmetric) {
            EXPECT_EQ(write(-kBound), canopen::AbortCode::None);
            EXPECT_EQ(write(-kBound - 1), canopen::AbortCode::ValueTooLow);
        }
    }
}

// Table 8-119: 0x607F at most the smaller of Maximal Motor Speed and Gear Maximal Speed, and with
// a gear (8.2.79) that on the load side, × denominator / numerator.
TEST_F(Epos2ObjectTable, MaximalProfileVelocityIsBoundedByMotorAndGearSpeedsAsTable8_119) {
    const auto write = [this](std::uint16_t index, std::uint8_t sub, std::uint32_t value) {
        return od.write(index, sub, canopen::encode(value));
    };
    ASSERT_EQ(write(0x6410, 4, 8000), canopen::AbortCode::None);
    EXPECT_EQ(write(0x607F, 0, 8000), canopen::AbortCode::None);
    EXPECT_EQ(write(0x607F, 0, 8001), canopen::AbortCode::ValueTooHigh);
    ASSERT_EQ(write(0x2230, 3, 6000), canopen::AbortCode::None); // gear maximal speed lower
    EXPECT_EQ(write(0x607F, 0, 6001), canopen::AbortCode::ValueTooHigh);
    ASSERT_EQ(write(0x2230, 1, 10), canopen::AbortCode::None); // gear 10 : 1
    EXPECT_EQ(write(0x607F, 0, 600), canopen::AbortCode::None);
    EXPECT_EQ(write(0x607F, 0, 601), canopen::AbortCode::ValueTooHigh);
    ASSERT_EQ(od.write(0x2230, 2, canopen::encode(std::uint16_t{3})), canopen::AbortCode::None);
    EXPECT_EQ(write(0x607F, 0, 1800), canopen::AbortCode::None); // 6000 · 3 / 10
    EXPECT_EQ(write(0x607F, 0, 1801), canopen::AbortCode::ValueTooHigh);
}

// Table 4-12: a value that is not in the list is "value range of parameter exceeded"
// (0x06090030), also beyond the list's ends, where a min ... max range says "too high / low".
TEST_F(Epos2ObjectTable, WritesOutsideAValueListAreRefusedAsValueRangeExceeded) {
    for (const ValueList& list : kValueLists) {
        SCOPED_TRACE(entry_name(list.index, list.sub));
        const DataType type = od.find(list.index, list.sub)->type;
        const auto [low, high] = std::ranges::minmax(list.values);
        for (std::int64_t value = low - 2; value <= high + 100; ++value) {
            const auto bytes = bytes_of(type, value);
            if (!bytes) {
                continue;
            }
            const bool listed = std::ranges::find(list.values, value) != list.values.end();
            EXPECT_EQ(od.write(list.index, list.sub, *bytes),
                      listed ? canopen::AbortCode::None : canopen::AbortCode::InvalidValue)
                << value;
        }
    }
}

// 8.2.95: "and 4 294 967 295 for disable".
TEST_F(Epos2ObjectTable, PositionWindowAcceptsTheDisableValue) {
    EXPECT_EQ(od.write(0x6067, 0, canopen::encode(std::uint32_t{0xFFFF'FFFF})),
              canopen::AbortCode::None);
    EXPECT_EQ(od.write(0x6067, 0, canopen::encode(std::uint32_t{0xFFFF'FFFE})),
              canopen::AbortCode::ValueTooHigh);
}

// 8.2.16: a changed configuration is no longer the verified one; bracketed objects of table
// 8-67 and non-persistent ones do not count.
TEST_F(Epos2ObjectTable, ChangedCheckedParameterResetsVerifyConfiguration) {
    const auto stamp = [this] {
        od.set_as(0x1020, 1, std::uint32_t{15'000});     // days since 1984-01-01
        od.set_as(0x1020, 2, std::uint32_t{43'200'000}); // ms after midnight
    };
    const auto stamped = [this] {
        return od.get_as<std::uint32_t>(0x1020, 1) == 15'000 &&
               od.get_as<std::uint32_t>(0x1020, 2) == 43'200'000;
    };
    stamp();
    ASSERT_EQ(od.write(0x6081, 0, canopen::encode(std::uint32_t{500})), canopen::AbortCode::None);
    ASSERT_EQ(od.write(0x6040, 0, canopen::encode(std::uint16_t{6})), canopen::AbortCode::None);
    EXPECT_TRUE(stamped()) << "profile velocity is bracketed, the controlword not persistent";

    ASSERT_EQ(od.write(0x6065, 0, canopen::encode(std::uint32_t{500})), canopen::AbortCode::None);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1020, 1), 0u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1020, 2), 0u);

    stamp();
    ASSERT_EQ(od.write(0x1400, 2, canopen::encode(std::uint8_t{1})), canopen::AbortCode::None);
    EXPECT_FALSE(stamped()) << "a PDO's transmission type is checked";
}

// 8.2.5
TEST_F(Epos2ObjectTable, ManufacturerDeviceNameIsAConstantEPOS2) {
    const canopen::SubObject* name = od.find(0x1008, 0);
    ASSERT_NE(name, nullptr);
    EXPECT_EQ(name->type, DataType::VisibleString);
    EXPECT_EQ(name->access, kConst);
    EXPECT_EQ(name->value, canopen::encode_string("EPOS2"));
}

// 8.2.15 / 8.2.37: product code and revision number are made of the version entries.
TEST_F(Epos2ObjectTable, IdentityIsMadeOfVendorVersionsAndSerialNumber) {
    const auto version = [this](std::uint8_t sub) {
        return std::uint32_t{od.get_as<std::uint16_t>(0x2003, sub)};
    };
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 1), 0x0000'00FBu);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 2), version(2) << 16 | version(3));
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 3), version(1) << 16 | version(4));
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 4), 0x3456'789Au);
    EXPECT_EQ(od.get_as<std::uint64_t>(0x2004, 0), 0x0000'0012'3456'789Au);
    EXPECT_EQ(version(2) & 0xFFF0, 0x6220u) << "EPOS2 24/5 is hardware version 0x622x";
    EXPECT_EQ(version(1), 0x2126u) << "the newest firmware of chapter 9";
    EXPECT_EQ(dictionary.node_config().identity, epos2_identity(0x0000'0012'3456'789A));
}

} // namespace
} // namespace eposp::drives::epos2
