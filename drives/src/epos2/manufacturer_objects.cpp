// The manufacturer-specific area of the EPOS2 (firmware specification 8.2.34 - 8.2.83) as data,
// for an EPOS2 24/5 where the specification gives values per hardware. The behaviour behind the
// objects belongs to the device and attaches to them through hooks and listeners.
#include "eposp/canopen/entry_builder.hpp"
#include "object_areas.hpp"

#include <array>
#include <fmt/format.h>

namespace eposp::drives::epos2 {
namespace {

using namespace canopen::od_types;
using canopen::Entry;

// 8.2.34 - 8.2.43
void add_interface_objects(canopen::ObjectDictionary& od, const Epos2DictionaryConfig& config) {
    add_var(od, 0x2000, "Node ID", kU8, kRW, config.node_id).range(1, 127).persistent();
    // 8.2.35, table 8-81: 5 is reserved and 8 (10 kbit/s) not supported; 9 detects the rate.
    add_var(od, 0x2001, "CAN Bitrate", kU16, kRW, 9).one_of({0, 1, 2, 3, 4, 6, 7, 9}).persistent();
    add_var(od, 0x2002, "RS232 Baudrate", kU16, kRW, 5).range(0, 5).persistent();

    od.add_object(0x2003, "Version", kRecord); // 8.2.37
    add_entry(od, 0x2003, 1, "Software Version", kU16, kRO, kSoftwareVersion);
    add_entry(od, 0x2003, 2, "Hardware Version", kU16, kRO, kHardwareVersion);
    add_entry(od, 0x2003, 3, "Application Number", kU16, kRO, kApplicationNumber);
    add_entry(od, 0x2003, 4, "Application Version", kU16, kRO, kApplicationVersion);
    add_entry(od, 0x2003, 5, "Internal Object", kU16, kRO, 0);

    add_var(od, 0x2004, "Serial Number", kU64, kConst,
            static_cast<std::int64_t>(config.serial_number));
    add_var(od, 0x2005, "RS232 Frame Timeout", kU16, kRW, 500).persistent();
    add_var(od, 0x2006, "USB Frame Timeout", kU16, kRW, 500).persistent();
    add_var(od, 0x2008, "Miscellaneous Configuration", kU16, kRW, 0).persistent();
    // 8.2.42: the code of table 8-81 of the bit rate in use.
    add_var(od, 0x200A, "CAN Bitrate Display", kU16, kRO, 0);
    od.add_object(0x200C, "Custom Persistent Memory", kRecord); // 8.2.43
    for (std::uint8_t sub = 1; sub <= 4; ++sub) {
        add_entry(od, 0x200C, sub, fmt::format("Custom Persistent Memory {}", sub), kU32, kRW, 0)
            .persistent();
    }
}

// 8.2.44 - 8.2.55
void add_sensor_and_setting_values(canopen::ObjectDictionary& od) {
    add_var(od, 0x2020, "Incremental Encoder 1 Counter", kU32, kRO, 0).pdo_mappable();
    add_var(od, 0x2021, "Incremental Encoder 1 Counter at Index Pulse", kU32, kRO, 0)
        .pdo_mappable();
    // 8.2.46 types it UNSIGNED16, table 8-67 UNSIGNED32: the section wins (three hall bits).
    add_var(od, 0x2022, "Hall Sensor Pattern", kU16, kRO, 0).pdo_mappable();
    add_var(od, 0x2027, "Current Actual Value Averaged", kI16, kRO, 0).pdo_mappable();
    add_var(od, 0x2028, "Velocity Actual Value Averaged", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x2029, "Auxiliary Velocity Actual Value Averaged", kI32, kRO, 0).pdo_mappable();
    // 8.2.50: "-Output current limit ... Output current limit".
    add_var(od, 0x2030, "Current Mode Setting Value", kI16, kRW, 0)
        .at_most(od, 0x6410, 2, /*symmetric=*/true)
        .pdo_mappable();
    // 8.2.51 types it INTEGER32, table 8-67 INTEGER16: the section wins.
    add_var(od, 0x2031, "Current Demand Value", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x2062, "Position Mode Setting Value", kI32, kRW, 0)
        .range(kI32Min, kI32Max)
        .pdo_mappable();
    add_var(od, 0x2069, "Auxiliary Velocity Sensor Actual Value", kI32, kRO, 0);
    add_var(od, 0x206B, "Velocity Mode Setting Value", kI32, kRW, 0)
        .at_most(od, 0x607F, 0, /*symmetric=*/true)
        .pdo_mappable();
    add_var(od, 0x206C, "Auxiliary Velocity Actual Value", kI32, kRO, 0);
}

// 8.2.56 - 8.2.61, for the six inputs and four outputs of an EPOS2 24/5.
void add_digital_io_objects(canopen::ObjectDictionary& od) {
    // Table 8-85, column EPOS2 24/5: general purpose A, B, C, home switch, positive and
    // negative limit switch.
    constexpr std::array<std::int64_t, 6> kInputDefaults = {15, 14, 13, 2, 1, 0};
    od.add_object(0x2070, "Configuration of Digital Inputs", kRecord);
    for (std::uint8_t n = 1; n <= kInputDefaults.size(); ++n) {
        add_entry(od, 0x2070, n, fmt::format("Configuration of Digital Input {}", n), kU16, kRW,
                  kInputDefaults[n - 1])
            .range(0, 15)
            .persistent();
    }
    od.add_object(0x2071, "Digital Input Functionalities", kRecord);
    add_entry(od, 0x2071, 1, "Digital Input Functionalities State", kU16, kRO, 0).pdo_mappable();
    add_entry(od, 0x2071, 2, "Digital Input Functionalities Mask", kU16, kRW, 0xE007).persistent();
    add_entry(od, 0x2071, 3, "Digital Input Functionalities Polarity", kU16, kRW, 0).persistent();
    add_entry(od, 0x2071, 4, "Digital Input Functionalities Execution Mask", kU16, kRW, 0x0008)
        .persistent();

    od.add_object(0x2074, "Position Marker", kRecord);
    add_entry(od, 0x2074, 1, "Position Marker captured Position", kI32, kRO, 0).pdo_mappable();
    add_entry(od, 0x2074, 2, "Position Marker Edge Type", kU8, kRW, 0).persistent();
    add_entry(od, 0x2074, 3, "Position Marker Mode", kU8, kRW, 1).range(0, 3).persistent();
    add_entry(od, 0x2074, 4, "Position Marker Counter", kU16, kRW, 0).pdo_mappable();
    add_entry(od, 0x2074, 5, "Position Marker History [1]", kI32, kRO, 0);
    add_entry(od, 0x2074, 6, "Position Marker History [2]", kI32, kRO, 0);

    od.add_object(0x2078, "Digital Output Functionalities", kRecord);
    add_entry(od, 0x2078, 1, "Digital Output Functionalities State", kU16, kRW, 0).pdo_mappable();
    add_entry(od, 0x2078, 2, "Digital Output Functionalities Mask", kU16, kRW, 0).persistent();
    add_entry(od, 0x2078, 3, "Digital Output Functionalities Polarity", kU16, kRW, 0).persistent();

    // Table 8-93, column EPOS2 24/5: general purpose OutA ... OutD.
    constexpr std::array<std::int64_t, 4> kOutputDefaults = {15, 14, 13, 12};
    od.add_object(0x2079, "Configuration of Digital Outputs", kRecord);
    for (std::uint8_t n = 1; n <= kOutputDefaults.size(); ++n) {
        add_entry(od, 0x2079, n, fmt::format("Configuration of Digital Output {}", n), kU16, kRW,
                  kOutputDefaults[n - 1])
            .range(0, 15)
            .persistent();
    }

    od.add_object(0x207A, "Position Compare", kRecord);
    add_entry(od, 0x207A, 1, "Position Compare Configuration", kU16, kRW, 0).pdo_mappable();
    add_entry(od, 0x207A, 2, "Position Compare Reference Position", kI32, kRW, 0).pdo_mappable();
    add_entry(od, 0x207A, 3, "Position Compare Interval Width", kI32, kRW, 0)
        .range(0, kI32Max)
        .persistent();
    add_entry(od, 0x207A, 4, "Position Compare Interval Repetitions", kU16, kRW, 0).persistent();
    add_entry(od, 0x207A, 5, "Position Compare Pulse Width", kU16, kRW, 0).persistent();
}

// 8.2.62 - 8.2.71
void add_analog_homing_interpolation_objects(canopen::ObjectDictionary& od) {
    // Table 8-97: 3..7 are reserved.
    od.add_object(0x207B, "Configuration of Analog Inputs", kArray);
    for (std::uint8_t n = 1; n <= 2; ++n) {
        add_entry(od, 0x207B, n, fmt::format("Configuration of Analog Input {}", n), kU16, kRW,
                  16 - n)
            .one_of({0, 1, 2, 8, 9, 10, 11, 12, 13, 14, 15})
            .persistent();
    }
    od.add_object(0x207C, "Analog Inputs", kRecord);
    for (std::uint8_t n = 1; n <= 2; ++n) {
        add_entry(od, 0x207C, n, fmt::format("Analog Input {}", n), kI16, kRO, 0).pdo_mappable();
    }
    // Table 8-67 lists one attribute column for 0x207D; read as "persistent", like the
    // execution mask of the digital inputs (0x2071 sub 4).
    add_var(od, 0x207D, "Analog Input Functionalities Execution Mask", kU16, kRW, 0).persistent();
    add_var(od, 0x207E, "Analog Output 1", kU16, kRW, 0).range(0, 10'000).pdo_mappable();

    add_var(od, 0x2080, "Current Threshold for Homing Mode", kU16, kRW, 500)
        .persistent()
        .pdo_mappable();
    // 8.2.67 types it INTEGER32 with a signed range, table 8-67 UNSIGNED32: the section wins.
    add_var(od, 0x2081, "Home Position", kI32, kRW, 0)
        .range(kI32Min, kI32Max)
        .persistent()
        .pdo_mappable();
    add_var(od, 0x2082, "Home Position Displacement", kI32, kRO, 0);

    // 8.2.69: a 64-bit structure (type 0x0040: position, velocity, time) written through a
    // PDO; kept as its 8 raw bytes, which CiA 301 types cannot name otherwise.
    add_var(od, 0x20C1, "Interpolation Data Record", kU64, kWO, 0).pdo_mappable();
    od.add_object(0x20C4, "Interpolation Buffer", kRecord);
    add_entry(od, 0x20C4, 1, "Interpolation Buffer Status", kU16, kRO, 0).pdo_mappable();
    add_entry(od, 0x20C4, 2, "Interpolation Buffer Underflow Warning", kU16, kRW, 4)
        .range(0, 63)
        .persistent();
    add_entry(od, 0x20C4, 3, "Interpolation Buffer Overflow Warning", kU16, kRW, 60)
        .range(1, 64)
        .persistent();
    add_var(od, 0x20F4, "Following Error Actual Value", kI16, kRO, 0).pdo_mappable();
}

// 8.2.72 - 8.2.79
void add_brake_sensor_gear_objects(canopen::ObjectDictionary& od) {
    const auto times = [&od](std::uint16_t index, const char* name,
                             std::array<const char*, 3> names,
                             std::array<std::int64_t, 3> defaults) {
        od.add_object(index, name, kRecord);
        for (std::uint8_t sub = 1; sub <= 3; ++sub) {
            add_entry(od, index, sub, names[sub - 1], kU16, kRW, defaults[sub - 1])
                .range(0, kU16Max)
                .persistent();
        }
    };
    times(0x2100, "Holding Brake Configuration",
          {"Brake Reaction Rise Time", "Brake Reaction Fall Time", "Brake Timeout"},
          {10, 10, 65535});
    times(0x2101, "Standstill Window Configuration",
          {"Standstill Window", "Standstill Window Time", "Standstill Timeout"}, {30, 50, 1000});

    // 8.2.74: sub-index 3 does not exist.
    od.add_object(0x2210, "Sensor Configuration", kRecord);
    add_entry(od, 0x2210, 1, "Pulse Number Incremental Encoder 1", kU32, kRW, 500)
        .range(16, 2'500'000)
        .persistent();
    add_entry(od, 0x2210, 2, "Position Sensor Type", kU16, kRW, 0x01).persistent();
    add_entry(od, 0x2210, 4, "Position Sensor Polarity", kU16, kRW, 0).persistent();

    od.add_object(0x2211, "SSI Encoder Configuration", kRecord);
    add_entry(od, 0x2211, 1, "SSI Encoder Datarate", kU16, kRW, 500).range(400, 2000).persistent();
    add_entry(od, 0x2211, 2, "SSI Encoder Number of Data Bits", kU16, kRW, 0x0C0D).persistent();
    add_entry(od, 0x2211, 3, "SSI Encoder Actual Position", kI32, kRO, 0);
    // Table 8-106: binary or Gray-coded.
    add_entry(od, 0x2211, 4, "SSI Encoding Type", kU16, kRW, 0).one_of({0, 1}).persistent();

    od.add_object(0x2212, "Incremental Encoder 2 Configuration", kRecord);
    add_entry(od, 0x2212, 1, "Incremental Encoder 2 Pulse Number", kU32, kRW, 500)
        .range(16, 2'500'000)
        .persistent();
    add_entry(od, 0x2212, 2, "Incremental Encoder 2 Counter", kU32, kRO, 0).pdo_mappable();
    add_entry(od, 0x2212, 3, "Incremental Encoder 2 Counter at Index Pulse", kU32, kRO, 0)
        .pdo_mappable();

    od.add_object(0x2213, "Sinus Incremental Encoder 2 Configuration", kRecord);
    add_entry(od, 0x2213, 1, "Sinus Incremental Encoder 2 Resolution", kU32, kRW, 0x0080'0006)
        .persistent();
    add_entry(od, 0x2213, 2, "Sinus Incremental Encoder 2 Actual Position", kI32, kRO, 0);

    // 8.2.78, table 8-108: the default is not given; 0 (single loop) is the only structure an
    // EPOS2 24/5 supports.
    add_var(od, 0x2220, "Controller Structure", kU16, kRW, 0).one_of({0, 1}).persistent();

    od.add_object(0x2230, "Gear Configuration", kRecord);
    add_entry(od, 0x2230, 1, "Gear Ratio Numerator", kU32, kRW, 0).range(0, kU32Max).persistent();
    add_entry(od, 0x2230, 2, "Gear Ratio Denominator", kU16, kRW, 1).range(1, kU16Max).persistent();
    add_entry(od, 0x2230, 3, "Gear Maximal Speed", kU32, kRW, 100'000)
        .range(1, kU32Max)
        .persistent();
}

// 8.2.80 - 8.2.83
void add_setpoint_input_objects(canopen::ObjectDictionary& od) {
    od.add_object(0x2300, "Digital Position Input", kRecord);
    add_entry(od, 0x2300, 1, "Digital Position Desired Value", kI32, kRO, 0);
    add_entry(od, 0x2300, 2, "Digital Position Scaling Numerator", kU16, kRW, 1).persistent();
    add_entry(od, 0x2300, 3, "Digital Position Scaling Denominator", kU16, kRW, 1).persistent();
    add_entry(od, 0x2300, 4, "Digital Position Polarity", kU8, kRW, 0).range(0, 1).persistent();
    add_entry(od, 0x2300, 5, "Digital Position Offset", kI32, kRW, 0).persistent();

    // 8.2.81 - 8.2.83: the same four entries for current, velocity and position setpoints; the
    // offset and the setpoint are 32 bits wide for velocity and position.
    const auto analog = [&od](std::uint16_t index, const char* what, canopen::DataType wide) {
        od.add_object(index, fmt::format("Analog {} Setpoint Configuration", what), kRecord);
        add_entry(od, index, 1, fmt::format("Analog {} Setpoint Scaling", what), kI16, kRW, 0)
            .persistent();
        add_entry(od, index, 2, fmt::format("Analog {} Setpoint Offset", what), wide, kRW, 0)
            .persistent();
        add_entry(od, index, 3, fmt::format("Analog {} Setpoint Notation Index", what), kI8, kRW, 0)
            .range(-2, 0)
            .persistent();
        add_entry(od, index, 4, fmt::format("Analog {} Setpoint", what), wide, kRO, 0);
    };
    analog(0x2301, "Current", kI16);
    analog(0x2302, "Velocity", kI32);
    // 8.2.82: the velocity offset is within +/- Maximal Profile Velocity.
    Entry(*od.find(0x2302, 2)).at_most(od, 0x607F, 0, /*symmetric=*/true);
    analog(0x2303, "Position", kI32);
}

} // namespace

void add_manufacturer_objects(canopen::ObjectDictionary& od, const Epos2DictionaryConfig& config) {
    add_interface_objects(od, config);
    add_sensor_and_setting_values(od);
    add_digital_io_objects(od);
    add_analog_homing_interpolation_objects(od);
    add_brake_sensor_gear_objects(od);
    add_setpoint_input_objects(od);
}

} // namespace eposp::drives::epos2
