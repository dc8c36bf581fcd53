// The ESCON2 dictionary against chapter 6 of the ESCON2 firmware specification, entry by
// entry. The rows are transcribed from the object tables of sections 6.2.1 - 6.2.81 (name, type,
// access, default, PDO mapping, persistence), for an ESCON2 Module 60/30 where a table gives
// values per hardware; the object list is table 34.
#include "eposp/canopen/eds_export.hpp"
#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/store_restore_objects.hpp"
#include "eposp/drives/escon2/escon2_dictionary.hpp"

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <optional>
#include <set>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

namespace eposp::drives::escon2 {
namespace {

using canopen::AbortCode;
using canopen::Access;
using canopen::DataType;
using canopen::ObjectCode;

constexpr auto kI8 = DataType::Integer8;
constexpr auto kI16 = DataType::Integer16;
constexpr auto kI32 = DataType::Integer32;
constexpr auto kU8 = DataType::Unsigned8;
constexpr auto kU16 = DataType::Unsigned16;
constexpr auto kU32 = DataType::Unsigned32;
constexpr auto kU64 = DataType::Unsigned64;
constexpr auto kRO = Access::ReadOnly;
constexpr auto kRW = Access::ReadWrite;
constexpr auto kVar = ObjectCode::Var;
constexpr auto kArray = ObjectCode::Array;
constexpr auto kRecord = ObjectCode::Record;

/// The default is "-" (a measured or computed value): not compared.
constexpr std::optional<std::int64_t> kAny;

// The flags of 6.1.4.
constexpr unsigned kP = 1;   ///< Persistent YES
constexpr unsigned kPdo = 2; ///< PDO mapping TXPDO or RXPDO

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
    {0x1000, 0, "Device type", kU32, kRO, 0x00020192, 0}, // 6.2.1
    {0x1001, 0, "Error register", kU8, kRO, kAny, 0}, // 6.2.2
    {0x1003, 0, "Number of errors", kU8, kRW, 0, 0}, // 6.2.3.1
    {0x1003, 1, "Error history 1", kU32, kRO, kAny, 0}, // 6.2.3.2
    {0x1003, 2, "Error history 2", kU32, kRO, kAny, 0}, // 6.2.3.3
    {0x1003, 3, "Error history 3", kU32, kRO, kAny, 0}, // 6.2.3.4
    {0x1003, 4, "Error history 4", kU32, kRO, kAny, 0}, // 6.2.3.5
    {0x1003, 5, "Error history 5", kU32, kRO, kAny, 0}, // 6.2.3.6
    {0x1010, 1, "Save all parameters", kU32, kRW, 0x00000001, 0}, // 6.2.5.1
    {0x1011, 1, "Restore all default parameters", kU32, kRW, 0x00000001, 0}, // 6.2.6.1
    {0x1018, 1, "Vendor ID", kU32, kRO, 0x000000FB, 0}, // 6.2.7.1
    {0x1018, 2, "Product code", kU32, kRO, kAny, 0}, // 6.2.7.2
    {0x1018, 3, "Revision number", kU32, kRO, kAny, 0}, // 6.2.7.3
    {0x1018, 4, "Serial number", kU32, kRO, kAny, 0}, // 6.2.7.4
    {0x2100, 1, "Serial number complete", kU64, kRO, kAny, 0}, // 6.2.8.1
    {0x210C, 1, "Custom persistent memory 1", kU32, kRW, 0x00000000, kP}, // 6.2.9.1
    {0x210C, 2, "Custom persistent memory 2", kU32, kRW, 0x00000000, kP}, // 6.2.9.2
    {0x210C, 3, "Custom persistent memory 3", kU32, kRW, 0x00000000, kP}, // 6.2.9.3
    {0x210C, 4, "Custom persistent memory 4", kU32, kRW, 0x00000000, kP}, // 6.2.9.4
    {0x2200, 1, "Power supply voltage", kU16, kRO, kAny, 0}, // 6.2.10.1
    {0x2201, 1, "Power supply undervoltage limit", kU32, kRW, 7500, kP}, // 6.2.11.1
    {0x2201, 2, "Power supply overvoltage limit", kU32, kRW, 65000, kP}, // 6.2.11.2
    {0x2202, 1, "Temperature logic section", kI16, kRO, kAny, kPdo}, // 6.2.12.1
    {0x3000, 1, "Sensors configuration", kU32, kRW, 0x00000110, kP}, // 6.2.13.1
    {0x3000, 2, "Control structure", kU32, kRW, 0x00020011, kP}, // 6.2.13.2
    {0x3000, 3, "Commutation sensors", kU32, kRW, 0x00000012, kP}, // 6.2.13.3
    {0x3000, 4, "Axis configuration miscellaneous", kU32, kRW, 0x00000000, kP}, // 6.2.13.4
    {0x3000, 5, "Main sensor resolution", kU32, kRO, kAny, 0}, // 6.2.13.5
    {0x3001, 1, "Nominal current", kU32, kRW, 30000, kP|kPdo}, // 6.2.14.1
    {0x3001, 2, "Output current limit", kU32, kRW, 60000, kP|kPdo}, // 6.2.14.2
    {0x3001, 3, "Number of pole pairs", kU8, kRW, 1, kP}, // 6.2.14.3
    {0x3001, 4, "Thermal time constant winding", kU16, kRW, 40, kP}, // 6.2.14.4
    {0x3001, 5, "Torque constant", kU32, kRW, 0, kP}, // 6.2.14.5
    {0x3002, 1, "Electrical resistance", kU32, kRW, 0, kP}, // 6.2.15.1
    {0x3002, 2, "Electrical inductance", kU16, kRW, 0, kP}, // 6.2.15.2
    {0x3010, 1, "Digital incremental encoder number of pulses", kU32, kRW, 500, kP}, // 6.2.16.1
    {0x3010, 2, "Digital incremental encoder type", kU16, kRW, 0x0000, kP}, // 6.2.16.2
    {0x301A, 1, "Digital Hall sensor type", kU16, kRW, 0x0000, kP}, // 6.2.17.1
    {0x301A, 2, "Digital Hall sensor pattern", kU16, kRO, kAny, 0}, // 6.2.17.2
    {0x30A0, 1, "Current controller P gain", kU32, kRW, 1171880, kP|kPdo}, // 6.2.18.1
    {0x30A0, 2, "Current controller I gain", kU32, kRW, 3906250, kP|kPdo}, // 6.2.18.2
    {0x30A2, 1, "Velocity controller P gain", kU32, kRW, 20000, kP|kPdo}, // 6.2.19.1
    {0x30A2, 2, "Velocity controller I gain", kU32, kRW, 500000, kP|kPdo}, // 6.2.19.2
    {0x30A2, 3, "Velocity controller FF velocity gain", kU32, kRW, 0, kP|kPdo}, // 6.2.19.3
    {0x30A2, 4, "Velocity controller FF acceleration gain", kU32, kRW, 0, kP|kPdo}, // 6.2.19.4
    {0x30A2, 5, "Velocity controller filter cut-off frequency", kU16, kRW, 600, kP}, // 6.2.19.5
    {0x30D0, 0, "Current demand value", kI32, kRO, kAny, kPdo}, // 6.2.20
    {0x30D1, 1, "Current actual value averaged", kI32, kRO, kAny, kPdo}, // 6.2.21.1
    {0x30D1, 2, "Current actual value", kI32, kRO, kAny, kPdo}, // 6.2.21.2
    {0x30D2, 1, "Torque actual value averaged", kI16, kRO, kAny, kPdo}, // 6.2.22.1
    {0x30D3, 1, "Velocity actual value averaged", kI32, kRO, kAny, kPdo}, // 6.2.23.1
    {0x30F0, 0, "Target current", kI32, kRW, 0, 0}, // 6.2.24
    {0x30F1, 0, "Current offset", kI32, kRW, 0, 0}, // 6.2.25
    {0x3141, 1, "Digital inputs logic state", kU16, kRO, kAny, kPdo}, // 6.2.26.1
    {0x3141, 2, "Digital inputs polarity", kU16, kRW, 0x0000, kP}, // 6.2.26.2
    {0x3142, 1, "Digital input 1 configuration", kU8, kRW, 16, kP}, // 6.2.27.1
    {0x3142, 2, "Digital input 2 configuration", kU8, kRW, 17, kP}, // 6.2.27.2
    {0x3142, 3, "Digital input 3 configuration", kU8, kRW, 18, kP}, // 6.2.27.3
    {0x3142, 4, "Digital input 4 configuration", kU8, kRW, 19, kP}, // 6.2.27.4
    {0x3142, 5, "High-speed digital input 1 configuration", kU8, kRW, 255, kP}, // 6.2.27.5
    {0x3142, 6, "High-speed digital input 2 configuration", kU8, kRW, 255, kP}, // 6.2.27.6
    {0x3142, 7, "High-speed digital input 3 configuration", kU8, kRW, 255, kP}, // 6.2.27.7
    {0x3142, 8, "High-speed digital input 4 configuration", kU8, kRW, 255, kP}, // 6.2.27.8
    {0x3143, 0, "Digital inputs functionality", kU32, kRO, kAny, kPdo}, // 6.2.28
    {0x3146, 1, "Set velocity value 0", kI32, kRW, 0, kP}, // 6.2.29.1
    {0x3146, 2, "Set velocity value 1", kI32, kRW, 0, kP}, // 6.2.29.2
    {0x3146, 3, "Set velocity value 2", kI32, kRW, 0, kP}, // 6.2.29.3
    {0x3146, 4, "Set velocity value 3", kI32, kRW, 0, kP}, // 6.2.29.4
    {0x3147, 1, "Set current value 0", kI32, kRW, 0, kP}, // 6.2.30.1
    {0x3147, 2, "Set current value 1", kI32, kRW, 0, kP}, // 6.2.30.2
    {0x3147, 3, "Set current value 2", kI32, kRW, 0, kP}, // 6.2.30.3
    {0x3147, 4, "Set current value 3", kI32, kRW, 0, kP}, // 6.2.30.4
    {0x314B, 1, "Digital input 1 PWM frequency", kU32, kRO, kAny, kPdo}, // 6.2.31.1
    {0x314B, 2, "Digital input 2 PWM frequency", kU32, kRO, kAny, kPdo}, // 6.2.31.2
    {0x314C, 1, "Digital input 1 PWM duty cycle", kU16, kRO, kAny, kPdo}, // 6.2.32.1
    {0x314C, 2, "Digital input 2 PWM duty cycle", kU16, kRO, kAny, kPdo}, // 6.2.32.2
    {0x3150, 1, "Digital outputs logic state", kU16, kRO, kAny, kPdo}, // 6.2.33.1
    {0x3150, 2, "Digital outputs polarity", kU16, kRW, 0x0000, kP}, // 6.2.33.2
    {0x3151, 1, "Digital output 1 configuration", kU8, kRW, 16, kP}, // 6.2.34.1
    {0x3151, 2, "Digital output 2 configuration", kU8, kRW, 17, kP}, // 6.2.34.2
    {0x3151, 3, "High-speed digital output 1 configuration", kU8, kRW, 255, kP}, // 6.2.34.3
    {0x3152, 0, "Digital outputs functionality", kU32, kRW, 0x0, kPdo}, // 6.2.35
    {0x3160, 1, "Analog input 1 voltage", kI16, kRO, kAny, kPdo}, // 6.2.36.1
    {0x3160, 2, "Analog input 2 voltage", kI16, kRO, kAny, kPdo}, // 6.2.36.2
    {0x3161, 1, "Analog input 1 configuration", kU8, kRW, 0, kP}, // 6.2.37.1
    {0x3161, 2, "Analog input 2 configuration", kU8, kRW, 1, kP}, // 6.2.37.2
    {0x3162, 1, "Analog input general purpose A", kI16, kRO, kAny, kPdo}, // 6.2.38.1
    {0x3162, 2, "Analog input general purpose B", kI16, kRO, kAny, kPdo}, // 6.2.38.2
    {0x3163, 1, "Analog input 1 adjustment offset", kI32, kRW, 0, kP}, // 6.2.39.1
    {0x3163, 2, "Analog input 1 adjustment gain factor", kU16, kRW, 10000, kP}, // 6.2.39.2
    {0x3163, 3, "Analog input 2 adjustment offset", kI32, kRW, 0, kP}, // 6.2.39.3
    {0x3163, 4, "Analog input 2 adjustment gain factor", kU16, kRW, 10000, kP}, // 6.2.39.4
    {0x3164, 1, "Analog input 1 raw value", kU16, kRO, kAny, kPdo}, // 6.2.40.1
    {0x3164, 2, "Analog input 2 raw value", kU16, kRO, kAny, kPdo}, // 6.2.40.2
    {0x3170, 1, "Analog output 1 voltage", kI16, kRO, kAny, kPdo}, // 6.2.41.1
    {0x3170, 2, "Analog output 2 voltage", kI16, kRO, kAny, kPdo}, // 6.2.41.2
    {0x3171, 1, "Analog output 1 configuration", kU8, kRW, 0, kP}, // 6.2.42.1
    {0x3171, 2, "Analog output 2 configuration", kU8, kRW, 1, kP}, // 6.2.42.2
    {0x3172, 1, "Analog output general purpose A", kI16, kRW, 0, kP|kPdo}, // 6.2.43.1
    {0x3172, 2, "Analog output general purpose B", kI16, kRW, 0, kP|kPdo}, // 6.2.43.2
    {0x3180, 1, "Velocity set value first duty cycle", kI32, kRW, 100, kP}, // 6.2.44.1
    {0x3180, 2, "Velocity set value first velocity", kI32, kRW, 0, kP}, // 6.2.44.2
    {0x3180, 3, "Velocity set value second duty cycle", kI32, kRW, 900, kP}, // 6.2.44.3
    {0x3180, 4, "Velocity set value second velocity", kI32, kRW, 0, kP}, // 6.2.44.4
    {0x3181, 1, "Velocity set value offset first duty cycle", kI32, kRW, 100, kP}, // 6.2.45.1
    {0x3181, 2, "Velocity set value offset first velocity", kI32, kRW, 0, kP}, // 6.2.45.2
    {0x3181, 3, "Velocity set value offset second duty cycle", kI32, kRW, 900, kP}, // 6.2.45.3
    {0x3181, 4, "Velocity set value offset second velocity", kI32, kRW, 0, kP}, // 6.2.45.4
    {0x3184, 1, "Current set value first duty cycle", kI32, kRW, 100, kP}, // 6.2.46.1
    {0x3184, 2, "Current set value first current", kI32, kRW, 0, kP}, // 6.2.46.2
    {0x3184, 3, "Current set value second duty cycle", kI32, kRW, 900, kP}, // 6.2.46.3
    {0x3184, 4, "Current set value second current", kI32, kRW, 0, kP}, // 6.2.46.4
    {0x3185, 1, "Current set value offset first duty cycle", kI32, kRW, 100, kP}, // 6.2.47.1
    {0x3185, 2, "Current set value offset first current", kI32, kRW, 0, kP}, // 6.2.47.2
    {0x3185, 3, "Current set value offset second duty cycle", kI32, kRW, 900, kP}, // 6.2.47.3
    {0x3185, 4, "Current set value offset second current", kI32, kRW, 0, kP}, // 6.2.47.4
    {0x31B0, 1, "Velocity set value first voltage", kI32, kRW, -10000, kP}, // 6.2.48.1
    {0x31B0, 2, "Velocity set value first velocity", kI32, kRW, 0, kP}, // 6.2.48.2
    {0x31B0, 3, "Velocity set value second voltage", kI32, kRW, 10000, kP}, // 6.2.48.3
    {0x31B0, 4, "Velocity set value second velocity", kI32, kRW, 0, kP}, // 6.2.48.4
    {0x31B1, 1, "Velocity set value offset first voltage", kI32, kRW, -10000, kP}, // 6.2.49.1
    {0x31B1, 2, "Velocity set value offset first velocity", kI32, kRW, 0, kP}, // 6.2.49.2
    {0x31B1, 3, "Velocity set value offset second voltage", kI32, kRW, 10000, kP}, // 6.2.49.3
    {0x31B1, 4, "Velocity set value offset second velocity", kI32, kRW, 0, kP}, // 6.2.49.4
    {0x31B4, 1, "Current set value first voltage", kI32, kRW, -10000, kP}, // 6.2.50.1
    {0x31B4, 2, "Current set value first current", kI32, kRW, 0, kP}, // 6.2.50.2
    {0x31B4, 3, "Current set value second voltage", kI32, kRW, 10000, kP}, // 6.2.50.3
    {0x31B4, 4, "Current set value second current", kI32, kRW, 0, kP}, // 6.2.50.4
    {0x31B5, 1, "Current set value offset first voltage", kI32, kRW, -10000, kP}, // 6.2.51.1
    {0x31B5, 2, "Current set value offset first current", kI32, kRW, 0, kP}, // 6.2.51.2
    {0x31B5, 3, "Current set value offset second voltage", kI32, kRW, 10000, kP}, // 6.2.51.3
    {0x31B5, 4, "Current set value offset second current", kI32, kRW, 0, kP}, // 6.2.51.4
    {0x31C1, 1, "Velocity actual first velocity", kI32, kRW, 0, kP}, // 6.2.52.1
    {0x31C1, 2, "Velocity actual first voltage", kI32, kRW, -4000, kP}, // 6.2.52.2
    {0x31C1, 3, "Velocity actual second velocity", kI32, kRW, 0, kP}, // 6.2.52.3
    {0x31C1, 4, "Velocity actual second voltage", kI32, kRW, 4000, kP}, // 6.2.52.4
    {0x31C2, 1, "Current actual first current", kI32, kRW, 0, kP}, // 6.2.53.1
    {0x31C2, 2, "Current actual first voltage", kI32, kRW, -4000, kP}, // 6.2.53.2
    {0x31C2, 3, "Current actual second current", kI32, kRW, 0, kP}, // 6.2.53.3
    {0x31C2, 4, "Current actual second voltage", kI32, kRW, 4000, kP}, // 6.2.53.4
    {0x31C3, 1, "Logic section temperature first temperature", kI32, kRW, 0, kP}, // 6.2.54.1
    {0x31C3, 2, "Logic section temperature first voltage", kI32, kRW, -4000, kP}, // 6.2.54.2
    {0x31C3, 3, "Logic section temperature second temperature", kI32, kRW, 0, kP}, // 6.2.54.3
    {0x31C3, 4, "Logic section temperature second voltage", kI32, kRW, 4000, kP}, // 6.2.54.4
    {0x31C3, 5, "Power stage temperature first temperature", kI32, kRW, 0, kP}, // 6.2.54.5
    {0x31C3, 6, "Power stage temperature first voltage", kI32, kRW, -4000, kP}, // 6.2.54.6
    {0x31C3, 7, "Power stage temperature second temperature", kI32, kRW, 0, kP}, // 6.2.54.7
    {0x31C3, 8, "Power stage temperature second voltage", kI32, kRW, 4000, kP}, // 6.2.54.8
    {0x3200, 1, "I2t level motor", kU16, kRO, kAny, kPdo}, // 6.2.55.1
    {0x3201, 1, "I2t level power stage", kU16, kRO, kAny, kPdo}, // 6.2.56.1
    {0x3201, 2, "Temperature power stage", kI16, kRO, kAny, kPdo}, // 6.2.56.2
    {0x3201, 3, "Max temperature power stage", kU16, kRW, 1100, kP}, // 6.2.56.3
    {0x3203, 1, "PWM duty cycle actual value", kU16, kRO, kAny, kPdo}, // 6.2.57.1
    {0x603F, 0, "Error code", kU16, kRO, kAny, kPdo}, // 6.2.58
    {0x6040, 0, "Controlword", kU16, kRW, kAny, kPdo}, // 6.2.59
    {0x6041, 0, "Statusword", kU16, kRO, kAny, kPdo}, // 6.2.60
    {0x6060, 0, "Modes of operation", kI8, kRW, -121, kP|kPdo}, // 6.2.61
    {0x6061, 0, "Modes of operation display", kI8, kRO, kAny, kPdo}, // 6.2.62
    {0x606B, 0, "Velocity demand value", kI32, kRO, kAny, kPdo}, // 6.2.63
    {0x606C, 0, "Velocity actual value", kI32, kRO, kAny, kPdo}, // 6.2.64
    {0x6076, 0, "Motor rated torque", kU32, kRW, 0, 0}, // 6.2.65
    {0x6077, 0, "Torque actual value", kI16, kRO, kAny, kPdo}, // 6.2.66
    {0x607F, 0, "Max profile velocity", kU32, kRW, 120000, kP|kPdo}, // 6.2.67
    {0x6080, 0, "Max motor speed", kU32, kRW, 120000, kP|kPdo}, // 6.2.68
    {0x6083, 0, "Profile acceleration", kU32, kRW, 10000, kP|kPdo}, // 6.2.69
    {0x6084, 0, "Profile deceleration", kU32, kRW, 10000, kP|kPdo}, // 6.2.70
    {0x6085, 0, "Quick stop deceleration", kU32, kRW, 10000, kP|kPdo}, // 6.2.71
    {0x60A9, 0, "SI unit velocity", kU32, kRW, 0x00B44700, kP}, // 6.2.72
    {0x60AA, 0, "SI unit acceleration", kU32, kRW, 0x00C00300, kP}, // 6.2.73
    {0x60B1, 0, "Velocity offset", kI32, kRW, 0, kPdo}, // 6.2.74
    {0x60C5, 0, "Max acceleration", kU32, kRW, 4294967295, kP|kPdo}, // 6.2.75
    {0x60E5, 1, "Velocity actual value sensor 1", kI32, kRO, kAny, kPdo}, // 6.2.76.1
    {0x60E5, 2, "Velocity actual value sensor 2", kI32, kRO, kAny, kPdo}, // 6.2.76.2
    {0x60E5, 9, "Velocity actual value averaged sensor 1", kI32, kRO, kAny, kPdo}, // 6.2.76.3
    {0x60E5, 10, "Velocity actual value averaged sensor 2", kI32, kRO, kAny, kPdo}, // 6.2.76.4
    {0x60FD, 0, "Digital inputs", kU32, kRO, kAny, kPdo}, // 6.2.77
    {0x60FE, 1, "Physical outputs", kU32, kRW, 0x0, kPdo}, // 6.2.78.1
    {0x60FF, 0, "Target velocity", kI32, kRW, 0, kPdo}, // 6.2.79
    {0x6402, 0, "Motor type", kU16, kRW, 10, kP}, // 6.2.80
    {0x6502, 0, "Supported drive modes", kU32, kRO, 0x00060000, kPdo}, // 6.2.81
};

/// Table 34.
const std::vector<std::pair<std::uint16_t, ObjectCode>> kObjectOverview = {
    {0x1000, kVar},
    {0x1001, kVar},
    {0x1003, kArray},
    {0x1008, kVar},
    {0x1010, kArray},
    {0x1011, kArray},
    {0x1018, kRecord},
    {0x2100, kRecord},
    {0x210C, kArray},
    {0x2200, kRecord},
    {0x2201, kRecord},
    {0x2202, kRecord},
    {0x3000, kRecord},
    {0x3001, kRecord},
    {0x3002, kRecord},
    {0x3010, kRecord},
    {0x301A, kRecord},
    {0x30A0, kRecord},
    {0x30A2, kRecord},
    {0x30D0, kVar},
    {0x30D1, kArray},
    {0x30D2, kArray},
    {0x30D3, kArray},
    {0x30F0, kVar},
    {0x30F1, kVar},
    {0x3141, kRecord},
    {0x3142, kArray},
    {0x3143, kVar},
    {0x3146, kArray},
    {0x3147, kArray},
    {0x314B, kArray},
    {0x314C, kArray},
    {0x3150, kRecord},
    {0x3151, kArray},
    {0x3152, kVar},
    {0x3160, kArray},
    {0x3161, kArray},
    {0x3162, kArray},
    {0x3163, kRecord},
    {0x3164, kArray},
    {0x3170, kArray},
    {0x3171, kArray},
    {0x3172, kArray},
    {0x3180, kRecord},
    {0x3181, kRecord},
    {0x3184, kRecord},
    {0x3185, kRecord},
    {0x31B0, kRecord},
    {0x31B1, kRecord},
    {0x31B4, kRecord},
    {0x31B5, kRecord},
    {0x31C1, kRecord},
    {0x31C2, kRecord},
    {0x31C3, kRecord},
    {0x3200, kRecord},
    {0x3201, kRecord},
    {0x3203, kRecord},
    {0x603F, kVar},
    {0x6040, kVar},
    {0x6041, kVar},
    {0x6060, kVar},
    {0x6061, kVar},
    {0x606B, kVar},
    {0x606C, kVar},
    {0x6076, kVar},
    {0x6077, kVar},
    {0x607F, kVar},
    {0x6080, kVar},
    {0x6083, kVar},
    {0x6084, kVar},
    {0x6085, kVar},
    {0x60A9, kVar},
    {0x60AA, kVar},
    {0x60B1, kVar},
    {0x60C5, kVar},
    {0x60E5, kArray},
    {0x60FD, kVar},
    {0x60FE, kArray},
    {0x60FF, kVar},
    {0x6402, kVar},
    {0x6502, kVar},
};

/// "Value range  min  max" of the object tables (Module 60/30 where the hardware decides).
struct SpecRange {
    std::uint16_t index;
    std::uint8_t sub;
    std::int64_t low;
    std::int64_t high;
};
const std::vector<SpecRange> kSpecRanges = {
    {0x6080, 0, 1, 120'000},    // table 101, brushless with one pole pair (before 0x3001 sub 3)
    {0x3001, 1, 0, 30'000},     // table 53
    {0x3001, 2, 0, 60'000},     // table 54
    {0x3001, 3, 1, 255},        // 6.2.14.3
    {0x3001, 4, 1, 10'000},     // 6.2.14.4
    {0x3001, 5, 0, 10'000'000}, // 6.2.14.5
    {0x3010, 1, 16, 2'500'000}, // 6.2.16.1
    {0x30A2, 5, 1, 10'000},     // 6.2.19.5
    {0x3146, 1, -120'000, 120'000}, {0x3146, 2, -120'000, 120'000},
    {0x3146, 3, -120'000, 120'000}, {0x3146, 4, -120'000, 120'000}, // 6.2.29
    {0x3147, 1, -60'000, 60'000}, {0x3147, 2, -60'000, 60'000},
    {0x3147, 3, -60'000, 60'000}, {0x3147, 4, -60'000, 60'000},     // 6.2.30
    {0x3163, 1, -1'000, 1'000}, {0x3163, 2, 5'000, 20'000},
    {0x3163, 3, -1'000, 1'000}, {0x3163, 4, 5'000, 20'000},         // 6.2.39
    {0x3172, 1, -4'000, 4'000}, {0x3172, 2, -4'000, 4'000},         // table 71
    {0x3180, 1, 100, 900}, {0x3180, 2, -120'000, 120'000},
    {0x3180, 3, 100, 900}, {0x3180, 4, -120'000, 120'000},          // 6.2.44
    {0x3181, 1, 100, 900}, {0x3181, 2, -120'000, 120'000},
    {0x3181, 3, 100, 900}, {0x3181, 4, -120'000, 120'000},          // 6.2.45
    {0x3184, 1, 100, 900}, {0x3184, 2, -60'000, 60'000},
    {0x3184, 3, 100, 900}, {0x3184, 4, -60'000, 60'000},            // 6.2.46
    {0x3185, 1, 100, 900}, {0x3185, 2, -60'000, 60'000},
    {0x3185, 3, 100, 900}, {0x3185, 4, -60'000, 60'000},            // 6.2.47
    {0x31B0, 1, -10'000, 10'000}, {0x31B0, 2, -120'000, 120'000},
    {0x31B0, 3, -10'000, 10'000}, {0x31B0, 4, -120'000, 120'000},   // 6.2.48, table 73
    {0x31B1, 1, -10'000, 10'000}, {0x31B1, 2, -120'000, 120'000},
    {0x31B1, 3, -10'000, 10'000}, {0x31B1, 4, -120'000, 120'000},   // 6.2.49
    {0x31B4, 1, -10'000, 10'000}, {0x31B4, 2, -60'000, 60'000},
    {0x31B4, 3, -10'000, 10'000}, {0x31B4, 4, -60'000, 60'000},     // 6.2.50
    {0x31B5, 1, -10'000, 10'000}, {0x31B5, 2, -60'000, 60'000},
    {0x31B5, 3, -10'000, 10'000}, {0x31B5, 4, -60'000, 60'000},     // 6.2.51
    {0x31C1, 2, -4'000, 4'000}, {0x31C1, 4, -4'000, 4'000},         // table 85
    {0x31C2, 2, -4'000, 4'000}, {0x31C2, 4, -4'000, 4'000},         // table 88
    {0x31C3, 2, -4'000, 4'000}, {0x31C3, 4, -4'000, 4'000},
    {0x31C3, 6, -4'000, 4'000}, {0x31C3, 8, -4'000, 4'000},         // 6.2.54
    {0x3201, 3, 0, 1'100},       // table 96, 0.1 °C
    {0x60C5, 0, 1, 4'294'967'295}, // 6.2.75
};

/// Value ranges bounded by another object ("1 … Max motor speed").
struct BoundedRange {
    std::uint16_t index;
    std::uint16_t bound_index;
};
const std::vector<BoundedRange> kBoundedRanges = {
    {0x607F, 0x6080}, // 6.2.67
    {0x6083, 0x60C5}, // 6.2.69
    {0x6084, 0x60C5}, // 6.2.70
    {0x6085, 0x60C5}, // 6.2.71
};

/// Value ranges given as a table of values or bits (refused with 0x06090030 otherwise).
struct ValueList {
    std::uint16_t index;
    std::uint8_t sub;
    std::vector<std::int64_t> values;
};
const std::vector<ValueList> kValueLists = {
    {0x3000, 1, {0x000, 0x010, 0x100, 0x110}},                     // table 47
    {0x3000, 2, {0x0000'0001, 0x0001'0011, 0x0002'0011}},         // table 49
    {0x3000, 4, {0x000, 0x001, 0x100, 0x101, 0x200, 0x201, 0x300, 0x301}}, // table 52
    {0x3010, 2, {0x000, 0x010, 0x200, 0x210}},                     // table 55
    {0x301A, 1, {0x00, 0x01, 0x10, 0x11}},                         // table 56
    {0x3142, 1, {255, 37, 36, 33, 32, 29, 28, 27, 23, 22, 21, 20, 19, 18, 17, 16, 15, 14, 13,
                 12}},                                             // table 59 [a]
    {0x3142, 2, {255, 37, 36, 33, 32, 29, 28, 27, 23, 22, 21, 20, 19, 18, 17, 16, 15, 14, 13,
                 12}},
    {0x3142, 3, {255, 29, 28, 27, 23, 22, 21, 20, 19, 18, 17, 16, 15, 14, 13, 12, 1, 0}},
    {0x3142, 8, {255, 29, 28, 27, 23, 22, 21, 20, 19, 18, 17, 16, 15, 14, 13, 12, 1, 0}},
    {0x3151, 1, {255, 33, 32, 26, 25, 18, 17, 16}},                // table 65
    {0x3151, 3, {255, 26, 25, 18, 17, 16}},                        // no Hall frequency on HsDigOut
    {0x3161, 1, {255, 11, 10, 9, 8, 1, 0}},                        // table 68
    {0x3171, 1, {255, 13, 12, 11, 10, 9, 8, 1, 0}},                // table 70
    {0x6060, 0, {-121, -120}},                                     // table 100
    {0x60A9, 0, {0x00B4'4700, 0xFDB4'4700}},                       // table 103
    {0x60AA, 0, {0x00C0'0300}},                                    // table 105
    {0x6402, 0, {1, 10}},                                          // table 108
};
// clang-format on

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
        throw std::invalid_argument("as_integer: not an integer type of table 30");
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

class Escon2ObjectTable : public ::testing::Test {
protected:
    static Escon2DictionaryConfig config() {
        Escon2DictionaryConfig config;
        config.serial_number = 0x0000'0012'3456'789A;
        config.parameter_file = "never-written.bin";
        return config;
    }

    AbortCode write(std::uint16_t index, std::uint8_t sub, std::int64_t value) {
        return od.write(index, sub, *bytes_of(od.find(index, sub)->type, value));
    }

    Escon2Dictionary dictionary{config()};
    canopen::ObjectDictionary& od = dictionary.objects();
};

TEST_F(Escon2ObjectTable, EveryEntryHasTheSpecifiedNameTypeAccessDefaultAndFlags) {
    for (const SpecEntry& row : kSpecTable) {
        SCOPED_TRACE(entry_name(row.index, row.sub) + ": " + row.name);
        const canopen::SubObject* sub = od.find(row.index, row.sub);
        if (sub == nullptr) {
            ADD_FAILURE() << "missing";
            continue;
        }
        EXPECT_EQ(sub->name, row.name);
        EXPECT_EQ(sub->type, row.type);
        EXPECT_EQ(sub->access, row.access);
        EXPECT_EQ(sub->persistent, (row.flags & kP) != 0);
        EXPECT_EQ(sub->pdo_mappable, (row.flags & kPdo) != 0);
        if (row.default_value) {
            EXPECT_EQ(as_integer(row.type, sub->default_value), *row.default_value);
            EXPECT_EQ(sub->value, sub->default_value);
        }
    }
}

TEST_F(Escon2ObjectTable, HasNoEntryTheSpecificationDoesNotList) {
    std::set<std::pair<std::uint16_t, std::uint8_t>> listed = {{0x1008, 0}};
    for (const SpecEntry& row : kSpecTable) {
        listed.emplace(row.index, row.sub);
    }
    for (const auto& [index, object] : od.objects()) {
        for (const auto& [sub_index, sub] : object.subs) {
            const bool highest_sub_index = object.code != kVar && sub_index == 0;
            EXPECT_TRUE(listed.contains({index, sub_index}) || highest_sub_index)
                << entry_name(index, sub_index) << " " << sub.name;
        }
    }
}

TEST_F(Escon2ObjectTable, HasExactlyTheObjectsOfTable34) {
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

// 6.2.3 / 6.2.76: "Highest subindex supported" as the object tables give it.
TEST_F(Escon2ObjectTable, HighestSubIndexIsTheSpecified) {
    const std::vector<std::pair<std::uint16_t, std::uint8_t>> highest = {
        {0x1010, 1}, {0x1011, 1}, {0x1018, 4}, {0x2100, 1}, {0x210C, 4}, {0x2201, 2},  {0x3000, 5},
        {0x3001, 5}, {0x3142, 8}, {0x3151, 3}, {0x31C3, 8}, {0x3201, 3}, {0x60E5, 10}, {0x60FE, 1}};
    for (const auto& [index, sub] : highest) {
        EXPECT_EQ(od.get_as<std::uint8_t>(index, 0), sub) << fmt::format("0x{:04X}", index);
    }
}

TEST_F(Escon2ObjectTable, WritesInsideTheValueRangeAreAcceptedAndOutsideRefused) {
    for (const SpecRange& range : kSpecRanges) {
        SCOPED_TRACE(entry_name(range.index, range.sub));
        EXPECT_EQ(write(range.index, range.sub, range.low), AbortCode::None);
        EXPECT_EQ(write(range.index, range.sub, range.high), AbortCode::None);
        const DataType type = od.find(range.index, range.sub)->type;
        if (const auto below = bytes_of(type, range.low - 1)) {
            EXPECT_EQ(od.write(range.index, range.sub, *below), AbortCode::ValueTooLow);
        }
        if (const auto above = bytes_of(type, range.high + 1)) {
            EXPECT_EQ(od.write(range.index, range.sub, *above), AbortCode::ValueTooHigh);
        }
    }
}

TEST_F(Escon2ObjectTable, WritesBeyondTheBoundingObjectAreRefused) {
    constexpr std::int64_t kBound = 1000;
    for (const BoundedRange& range : kBoundedRanges) {
        SCOPED_TRACE(entry_name(range.index, 0));
        ASSERT_EQ(write(range.bound_index, 0, kBound), AbortCode::None);
        EXPECT_EQ(write(range.index, 0, kBound), AbortCode::None);
        EXPECT_EQ(write(range.index, 0, kBound + 1), AbortCode::ValueTooHigh);
        EXPECT_EQ(write(range.index, 0, 0), AbortCode::ValueTooLow);
    }
}

// Table 111: a value the object's table does not list is "Value range error" (0x06090030). The
// mapping objects start unmapped, so that no rule of tables 59, 65 and 68 meets another mapping.
TEST_F(Escon2ObjectTable, WritesOutsideAValueListAreRefusedAsValueRangeError) {
    for (const std::uint16_t index : std::vector<std::uint16_t>{0x3142, 0x3151, 0x3161, 0x3171}) {
        for (const auto& [sub, entry] : od.find(index)->subs) {
            if (sub != 0) {
                od.set_as(index, sub, std::uint8_t{255});
            }
        }
    }
    for (const ValueList& list : kValueLists) {
        SCOPED_TRACE(entry_name(list.index, list.sub));
        // Both sensors for the control structures, the high-speed pins free for the inputs.
        od.set_as(0x3000, 1, std::uint32_t{list.index == 0x3000 ? 0x110U : 0x010U});
        const DataType type = od.find(list.index, list.sub)->type;
        const auto [low, high] = std::ranges::minmax(list.values);
        const canopen::Bytes unmapped = od.get(list.index, list.sub);
        const auto probe = [&](std::int64_t value) {
            const auto bytes = bytes_of(type, value);
            if (!bytes) {
                return;
            }
            const bool listed = std::ranges::find(list.values, value) != list.values.end();
            EXPECT_EQ(od.write(list.index, list.sub, *bytes),
                      listed ? AbortCode::None : AbortCode::InvalidValue)
                << value;
            od.set(list.index, list.sub, unmapped); // the next probe meets no mapping of this one
        };
        for (std::int64_t value = low - 2; value <= std::min(high + 2, low + 1000); ++value) {
            probe(value);
        }
        for (const std::int64_t value : list.values) {
            probe(value);
            probe(value + 1);
        }
    }
}

// 6.2.4
TEST_F(Escon2ObjectTable, ManufacturerDeviceNameIsESCON2) {
    const canopen::SubObject* name = od.find(0x1008, 0);
    ASSERT_NE(name, nullptr);
    EXPECT_EQ(name->type, DataType::VisibleString);
    EXPECT_EQ(name->access, kRO);
    EXPECT_EQ(name->value, canopen::encode_string("ESCON2"));
}

// 6.2.7, 6.2.8, tables 40 and 112: hardware 0x1101 : application 0x1000, firmware 0x0100 :
// version 0x0000, the serial number's low 32 bits of the full 64 of 0x2100.
TEST_F(Escon2ObjectTable, IdentityIsMadeOfHardwareVersionsAndSerialNumber) {
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 1), 0x0000'00FBu);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 2), 0x1101'1000u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 3), 0x0100'0000u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 4), 0x3456'789Au);
    EXPECT_EQ(od.get_as<std::uint64_t>(0x2100, 1), 0x0000'0012'3456'789Au);
    EXPECT_EQ(escon2_identity(Escon2Hardware::Nano24_2, 0).product_code, 0x1103'1000u);
    EXPECT_EQ(escon2_identity(Escon2Hardware::Micro60_5, 0).product_code, 0x1102'1000u);
    EXPECT_EQ(escon2_identity(Escon2Hardware::Compact60_30, 0).product_code, 0x1101'1000u);
}

// Tables 41 - 97 for the smallest hardware: its defaults and ranges, not the Module's.
TEST_F(Escon2ObjectTable, NanoHasItsOwnHardwareDefaultsAndRanges) {
    Escon2DictionaryConfig nano_config;
    nano_config.hardware = Escon2Hardware::Nano24_2;
    Escon2Dictionary nano(nano_config);
    auto& objects = nano.objects();
    EXPECT_EQ(objects.get_as<std::uint32_t>(0x2201, 1), 4'500u);
    EXPECT_EQ(objects.get_as<std::uint32_t>(0x2201, 2), 31'000u);
    EXPECT_EQ(objects.get_as<std::uint32_t>(0x3001, 1), 2'000u);
    EXPECT_EQ(objects.get_as<std::uint32_t>(0x3001, 2), 6'000u);
    EXPECT_EQ(objects.get_as<std::int32_t>(0x31B0, 1), 0);
    EXPECT_EQ(objects.get_as<std::int32_t>(0x31B0, 3), 5'000);
    EXPECT_EQ(objects.get_as<std::int32_t>(0x31C1, 2), 0);
    EXPECT_EQ(objects.get_as<std::int32_t>(0x31C1, 4), 3'300);
    EXPECT_EQ(objects.get_as<std::uint16_t>(0x3201, 3), 900u);
    EXPECT_EQ(objects.write(0x3001, 1, canopen::encode(std::uint32_t{2'001})),
              AbortCode::ValueTooHigh);
    EXPECT_EQ(objects.write(0x3172, 1, canopen::encode(std::int16_t{-1})), AbortCode::ValueTooLow);
    EXPECT_EQ(objects.write(0x3147, 1, canopen::encode(std::int32_t{6'001})),
              AbortCode::ValueTooHigh);
}

// 6.2.11: under < over − over hysteresis − under hysteresis (250 mV + 1000 mV on the Module).
TEST_F(Escon2ObjectTable, SupplyLimitsKeepBothHysteresesApart) {
    ASSERT_EQ(write(0x2201, 2, 20'000), AbortCode::None);
    EXPECT_EQ(write(0x2201, 1, 18'750), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(write(0x2201, 1, 18'749), AbortCode::None);
    EXPECT_EQ(write(0x2201, 2, 19'999), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(write(0x2201, 2, 20'000), AbortCode::None);
    EXPECT_EQ(write(0x2201, 1, 7'499), AbortCode::ValueTooLow);
    EXPECT_EQ(write(0x2201, 2, 65'001), AbortCode::ValueTooHigh);
}

// 6.2.13: the main sensor and the commutation sensors must be configured and suit the motor.
TEST_F(Escon2ObjectTable, AxisConfigurationFollowsSensorsAndMotorType) {
    EXPECT_EQ(write(0x3000, 3, 0x00), AbortCode::ParameterIncompatibility) << "EC needs one";
    ASSERT_EQ(write(0x3000, 1, 0x010), AbortCode::None); // Hall sensor only
    EXPECT_EQ(write(0x3000, 2, 0x0002'0011), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(write(0x3000, 3, 0x12), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(write(0x3000, 2, 0x0001'0011), AbortCode::None);
    EXPECT_EQ(write(0x3000, 3, 0x10), AbortCode::None);

    ASSERT_EQ(write(0x3000, 1, 0x100), AbortCode::None);
    ASSERT_EQ(write(0x6402, 0, 1), AbortCode::None); // brushed DC
    EXPECT_EQ(write(0x3000, 1, 0x110), AbortCode::ParameterIncompatibility) << "no Hall on DC";
    EXPECT_EQ(write(0x3000, 2, 0x0001'0011), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(write(0x3000, 2, 0x0002'0011), AbortCode::None);
    EXPECT_EQ(write(0x3000, 3, 0x10), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(write(0x3000, 3, 0x00), AbortCode::None);
}

// Tables 59 and 68: a functionality once; one source per set value [e]; PWM only on inputs 1
// and 2 [a]; nothing on the high-speed inputs while sensor 2 (the encoder) uses them.
TEST_F(Escon2ObjectTable, DigitalInputMappingRules) {
    EXPECT_EQ(write(0x3142, 1, 17), AbortCode::ParameterIncompatibility) << "B is on input 2";
    EXPECT_EQ(write(0x3142, 5, 27), AbortCode::ParameterIncompatibility) << "sensor 2 there";
    EXPECT_EQ(write(0x3142, 1, 32), AbortCode::None);
    EXPECT_EQ(write(0x3161, 1, 9), AbortCode::ParameterIncompatibility) << "PWM sets velocity";
    EXPECT_EQ(write(0x3142, 3, 12), AbortCode::ParameterIncompatibility) << "so do switches";
    EXPECT_EQ(write(0x3161, 1, 11), AbortCode::None) << "the offset has its own source";
    EXPECT_EQ(write(0x3142, 2, 33), AbortCode::ParameterIncompatibility);
    ASSERT_EQ(write(0x3142, 1, 255), AbortCode::None);
    EXPECT_EQ(write(0x3142, 3, 12), AbortCode::None);
    EXPECT_EQ(write(0x3142, 4, 13), AbortCode::None) << "both switches select one value";
    EXPECT_EQ(write(0x3161, 2, 11), AbortCode::ParameterIncompatibility) << "mapped once";
    ASSERT_EQ(write(0x3000, 1, 0x010), AbortCode::None);
    EXPECT_EQ(write(0x3142, 5, 27), AbortCode::None);
}

// 6.2.34: the Hall frequencies need the Hall sensor, one of them at a time, not on HsDigOut1.
TEST_F(Escon2ObjectTable, DigitalOutputMappingRules) {
    EXPECT_EQ(write(0x3151, 1, 17), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(write(0x3151, 1, 32), AbortCode::None);
    EXPECT_EQ(write(0x3151, 2, 33), AbortCode::ParameterIncompatibility);
    EXPECT_EQ(write(0x3151, 3, 25), AbortCode::ParameterIncompatibility) << "sensor 2 there";
    ASSERT_EQ(write(0x3000, 1, 0x100), AbortCode::None);
    EXPECT_EQ(write(0x3151, 2, 33), AbortCode::ParameterIncompatibility) << "no Hall sensor";
}

// 6.2.65: nominal current × torque constant, not writable; 6.2.68 table 101: 120'000 rpm
// divided by the pole pairs of a brushless motor.
TEST_F(Escon2ObjectTable, RatedTorqueAndMaxMotorSpeedFollowTheMotorData) {
    ASSERT_EQ(write(0x3001, 1, 2'000), AbortCode::None);
    ASSERT_EQ(write(0x3001, 5, 25'500), AbortCode::None);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x6076, 0), 51'000u);
    EXPECT_EQ(write(0x6076, 0, 1), AbortCode::ReadOnly);
    ASSERT_EQ(write(0x3001, 3, 4), AbortCode::None);
    EXPECT_EQ(write(0x6080, 0, 30'001), AbortCode::ValueTooHigh);
    EXPECT_EQ(write(0x6080, 0, 30'000), AbortCode::None);
    ASSERT_EQ(write(0x6402, 0, 1), AbortCode::None);
    EXPECT_EQ(write(0x6080, 0, 120'000), AbortCode::None) << "a DC motor has no pole pairs";
}

// "Write access is only permitted in device state «Power Disable»".
TEST_F(Escon2ObjectTable, PowerDisableObjectsAreRefusedWhileThePowerStageIsOn) {
    bool disabled = false;
    Escon2DictionaryConfig guarded_config;
    guarded_config.power_disabled = [&disabled] {
        return disabled;
    };
    Escon2Dictionary guarded(guarded_config);
    auto& objects = guarded.objects();
    const auto write_u32 = [&objects](std::uint16_t index, std::uint8_t sub, std::uint32_t v) {
        return objects.write(index, sub, canopen::encode(v));
    };
    EXPECT_EQ(write_u32(0x3000, 4, 1), AbortCode::DeviceState);
    EXPECT_EQ(write_u32(0x60A9, 0, 0xFDB4'4700), AbortCode::DeviceState);
    EXPECT_EQ(objects.write(0x6402, 0, canopen::encode(std::uint16_t{1})), AbortCode::DeviceState);
    EXPECT_EQ(objects.write(0x31B0, 2, canopen::encode(std::int32_t{1000})),
              AbortCode::DeviceState);
    EXPECT_EQ(write_u32(0x1011, 1, canopen::kLoadSignature), AbortCode::DeviceState);
    EXPECT_EQ(write_u32(0x3001, 1, 1000), AbortCode::None) << "the nominal current any time";
    disabled = true;
    EXPECT_EQ(write_u32(0x3000, 4, 1), AbortCode::None);
    EXPECT_EQ(write_u32(0x60A9, 0, 0xFDB4'4700), AbortCode::None);
    EXPECT_EQ(write_u32(0x1011, 1, canopen::kLoadSignature), AbortCode::None);
}

// 6.2.5, 6.2.6, 6.2.9: "save" keeps the persistent objects (the custom memory among them) over
// a power cycle, "load" brings the defaults back at the next one.
TEST_F(Escon2ObjectTable, StoreAndRestoreKeepCustomPersistentMemory) {
    const auto file = std::filesystem::temp_directory_path() /
                      fmt::format("escon2-store-{}-{}.bin", ::getpid(),
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove(file);
    Escon2DictionaryConfig stored;
    stored.parameter_file = file;
    {
        Escon2Dictionary device(stored);
        auto& objects = device.objects();
        EXPECT_EQ(objects.get_as<std::uint32_t>(0x1010, 1), 1u) << "saves on command";
        ASSERT_EQ(objects.write(0x210C, 3, canopen::encode(std::uint32_t{0xCAFE})),
                  AbortCode::None);
        ASSERT_EQ(objects.write(0x30F0, 0, canopen::encode(std::int32_t{500})), AbortCode::None);
        EXPECT_EQ(objects.write(0x1010, 1, canopen::encode(std::uint32_t{1})),
                  AbortCode::TransferOrStore)
            << "only the signature \"save\"";
        ASSERT_EQ(objects.write(0x1010, 1, canopen::encode(canopen::kSaveSignature)),
                  AbortCode::None);
    }
    {
        Escon2Dictionary device(stored);
        EXPECT_EQ(device.power_up().status, canopen::StoredValuesStatus::Applied);
        EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x210C, 3), 0xCAFEu);
        EXPECT_EQ(device.objects().get_as<std::int32_t>(0x30F0, 0), 0) << "not persistent";
        ASSERT_EQ(device.objects().write(0x1011, 1, canopen::encode(canopen::kLoadSignature)),
                  AbortCode::None);
        EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x210C, 3), 0xCAFEu)
            << "defaults only after the next power cycle";
    }
    Escon2Dictionary device(stored);
    device.power_up();
    EXPECT_EQ(device.objects().get_as<std::uint32_t>(0x210C, 3), 0u);
    std::filesystem::remove(file);
}

// 6.2.3: five entries; writing 0 empties the history.
TEST_F(Escon2ObjectTable, ErrorHistoryHoldsFiveEntriesAndIsClearedByZero) {
    canopen::ErrorHistory history(od);
    for (std::uint32_t code = 1; code <= 7; ++code) {
        history.record(code);
    }
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1003, 0), 5u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1003, 1), 7u);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1003, 5), 3u);
    EXPECT_EQ(od.write(0x1003, 0, canopen::encode(std::uint8_t{0})), AbortCode::None);
    EXPECT_TRUE(history.entries().empty());
}

TEST_F(Escon2ObjectTable, ExportsAnEdsOfEveryObject) {
    const std::string eds =
        canopen::export_eds(od, escon2_device_info(Escon2Hardware::Module60_30));
    EXPECT_NE(eds.find("ProductName=ESCON2 Module 60/30"), std::string::npos);
    for (const auto& [index, code] : kObjectOverview) {
        EXPECT_NE(eds.find(fmt::format("[{:04X}]", index)), std::string::npos)
            << fmt::format("0x{:04X}", index);
    }
}

} // namespace
} // namespace eposp::drives::escon2
