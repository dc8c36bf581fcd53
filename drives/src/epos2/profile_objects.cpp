// The CiA 402 profile area of the EPOS2 (firmware specification 8.2.84 - 8.2.131) as data, with
// the units and factor group objects of 3.3 (0x6089 - 0x608E), for an EPOS2 24/5. Ranges bounded
// by another object ("1 ... Maximal Profile Velocity") are checked against its current value,
// 0x607F against table 8-119 (motor and gear speeds); that of table 8-126 (a function of motor
// type and pole pairs) keeps only its static bound.
#include "eposp/canopen/entry_builder.hpp"
#include "object_areas.hpp"
#include "velocity_units.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <span>

namespace eposp::drives::epos2 {
namespace {

using namespace canopen::od_types;
using canopen::Entry;

// 8.2.84 - 8.2.91
void add_device_control_objects(canopen::ObjectDictionary& od) {
    add_var(od, 0x6007, "Abort Connection Option Code", kI16, kRW, 3).range(1, 3).persistent();
    add_var(od, 0x6040, "Controlword", kU16, kRW, 0).pdo_mappable();
    add_var(od, 0x6041, "Statusword", kU16, kRO, 0).pdo_mappable();
    add_var(od, 0x605B, "Shutdown Option Code", kI16, kRW, 0).range(0, 1).persistent();
    add_var(od, 0x605C, "Disable Operation Option Code", kI16, kRW, 1).range(0, 1).persistent();
    add_var(od, 0x605E, "Fault Reaction Option Code", kI16, kRW, 2).range(-1, 2).persistent();
    // Table 8-118: the modes of operation.
    add_var(od, 0x6060, "Modes of Operation", kI8, kRW, 1)
        .one_of({7, 6, 3, 1, -1, -2, -3, -4, -5, -6})
        .pdo_mappable();
    add_var(od, 0x6061, "Modes of Operation Display", kI8, kRO, 1).pdo_mappable();
}

// 8.2.92 - 8.2.104
void add_position_velocity_objects(canopen::ObjectDictionary& od) {
    add_var(od, 0x6062, "Position Demand Value", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x6064, "Position Actual Value", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x6065, "Maximal Following Error", kU32, kRW, 2000)
        .range(0, kU32Max)
        .persistent()
        .pdo_mappable();
    // 8.2.95: "0 ... 2 147 483 647 (and 4 294 967 295 for disable)".
    constexpr std::uint32_t kWindowOff = 0xFFFF'FFFF;
    add_var(od, 0x6067, "Position Window", kU32, kRW, kWindowOff)
        .range(0, kU32Max)
        .persistent()
        .sub()
        .on_write = [](std::span<const std::uint8_t> value) {
        const auto window = canopen::decode<std::uint32_t>(value);
        return window <= kI32Max || window == kWindowOff ? canopen::AbortCode::None
                                                         : canopen::AbortCode::ValueTooHigh;
    };
    add_var(od, 0x6068, "Position Window Time", kU16, kRW, 0).range(0, kU16Max).persistent();
    add_var(od, 0x6069, "Velocity Sensor Actual Value", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x606B, "Velocity Demand Value", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x606C, "Velocity Actual Value", kI32, kRO, 0).pdo_mappable();
    add_var(od, 0x606D, "Velocity Window", kU32, kRW, kU32Max).range(0, kU32Max).persistent();
    add_var(od, 0x606E, "Velocity Window Time", kU16, kRW, 0).persistent();
    add_var(od, 0x6078, "Current Actual Value", kI16, kRO, 0).pdo_mappable();
    add_var(od, 0x607A, "Target Position", kI32, kRW, 0).range(kI32Min, kI32Max).pdo_mappable();
    add_var(od, 0x607C, "Home Offset", kI32, kRW, 0)
        .range(kI32Min, kI32Max)
        .persistent()
        .pdo_mappable();
}

// 8.2.105 - 8.2.111
void add_profile_motion_objects(canopen::ObjectDictionary& od) {
    od.add_object(0x607D, "Software Position Limit", kArray);
    add_entry(od, 0x607D, 1, "Minimal Position Limit", kI32, kRW, kI32Min)
        .range(kI32Min, kI32Max)
        .persistent();
    add_entry(od, 0x607D, 2, "Maximal Position Limit", kI32, kRW, kI32Max)
        .range(kI32Min, kI32Max)
        .persistent();
    // 8.2.106: the upper bound follows table 8-119 (bound_maximal_profile_velocity).
    add_var(od, 0x607F, "Maximal Profile Velocity", kU32, kRW, 25'000)
        .range(1, kU32Max)
        .persistent();
    add_var(od, 0x6081, "Profile Velocity", kU32, kRW, 1000)
        .range(1, kU32Max)
        .at_most(od, 0x607F, 0)
        .persistent()
        .pdo_mappable();
    for (const auto& [index, name] :
         {std::pair{0x6083, "Profile Acceleration"}, std::pair{0x6084, "Profile Deceleration"},
          std::pair{0x6085, "Quickstop Deceleration"}}) {
        add_var(od, static_cast<std::uint16_t>(index), name, kU32, kRW, 10'000)
            .range(1, kU32Max)
            .at_most(od, 0x60C5, 0)
            .persistent()
            .pdo_mappable();
    }
    // Table 8-120: 0 linear ramp (trapezoidal), 1 sin² ramp.
    add_var(od, 0x6086, "Motion Profile Type", kI16, kRW, 0)
        .one_of({0, 1})
        .persistent()
        .pdo_mappable();
}

// 8.2.112 - 8.2.117 and 3.3: position in quadcounts (notation 0, dimension 0xAC "steps"),
// velocity in rpm with notation 0, -1, -2 or -3 (dimension 0xA4), acceleration in rpm/s.
void add_factor_group_objects(canopen::ObjectDictionary& od) {
    add_var(od, 0x6089, "Position Notation Index", kI8, kRW, 0).range(0, 0).persistent();
    add_var(od, 0x608A, "Position Dimension Index", kU8, kRW, 0xAC).range(0xAC, 0xAC).persistent();
    add_var(od, 0x608B, "Velocity Notation Index", kI8, kRW, 0).range(-3, 0).persistent();
    add_var(od, 0x608C, "Velocity Dimension Index", kU8, kRW, 0xA4).range(0xA4, 0xA4).persistent();
    add_var(od, 0x608D, "Acceleration Notation Index", kI8, kRW, 0).range(0, 0).persistent();
    add_var(od, 0x608E, "Acceleration Dimension Index", kU8, kRW, 0xA4)
        .range(0xA4, 0xA4)
        .persistent();
}

// 8.2.118 - 8.2.124
void add_homing_interpolation_objects(canopen::ObjectDictionary& od) {
    // Table 8-121 (the "Value Range" row prints "–": the table is the range).
    add_var(od, 0x6098, "Homing Method", kI8, kRW, 7)
        .one_of({35, 34, 33, 27, 23, 18, 17, 11, 7, 2, 1, 0, -1, -2, -3, -4})
        .persistent()
        .pdo_mappable();
    od.add_object(0x6099, "Homing Speeds", kArray);
    add_entry(od, 0x6099, 1, "Speed for Switch Search", kU32, kRW, 100)
        .at_most(od, 0x607F, 0)
        .persistent()
        .pdo_mappable();
    add_entry(od, 0x6099, 2, "Speed for Zero Search", kU32, kRW, 10)
        .at_most(od, 0x607F, 0)
        .persistent()
        .pdo_mappable();
    add_var(od, 0x609A, "Homing Acceleration", kU32, kRW, 1000)
        .at_most(od, 0x60C5, 0)
        .persistent()
        .pdo_mappable();

    add_var(od, 0x60C0, "Interpolation Sub Mode Selection", kI16, kRW, -1).range(-1, -1);
    // 8.2.122 prints both entries as sub-index 0x01; the index is sub-index 2 (CiA 402).
    od.add_object(0x60C2, "Interpolation Time Period", kRecord);
    add_entry(od, 0x60C2, 1, "Interpolation Time Period Value", kU8, kRW, 1).range(1, 1);
    add_entry(od, 0x60C2, 2, "Interpolation Time Index", kI8, kRW, -3).range(-3, -3);

    // 8.2.123: the buffer holds 64 records of 8 bytes.
    od.add_object(0x60C4, "Interpolation Data Configuration", kRecord);
    add_entry(od, 0x60C4, 1, "Maximum Buffer Size", kU32, kRO, 64).range(64, 64);
    add_entry(od, 0x60C4, 2, "Actual Buffer Size", kU32, kRO, 0).range(0, 64).pdo_mappable();
    add_entry(od, 0x60C4, 3, "Buffer Organization", kU8, kRW, 0).range(0, 0);
    add_entry(od, 0x60C4, 4, "Buffer Position", kU16, kRW, 0).range(0, 64);
    add_entry(od, 0x60C4, 5, "Size of Data Record", kU8, kWO, 8).range(8, 8);
    add_entry(od, 0x60C4, 6, "Buffer Clear", kU8, kWO, 0).range(0, 1).pdo_mappable();
    add_var(od, 0x60C5, "Max Acceleration", kU32, kRW, kU32Max).range(1, kU32Max).persistent();
}

// 8.2.125 - 8.2.128. The spec gives the gains "depending on hardware" without values: they
// start at 0 (no control action) until a motor configuration sets them.
void add_control_parameter_objects(canopen::ObjectDictionary& od) {
    const auto gain = [&od](std::uint16_t index, std::uint8_t sub, std::string name) {
        add_entry(od, index, sub, std::move(name), kI16, kRW, 0)
            .range(0, 32'767)
            .persistent()
            .pdo_mappable();
    };
    const auto feed_forward = [&od](std::uint16_t index, std::uint8_t sub, std::string name) {
        add_entry(od, index, sub, std::move(name), kU16, kRW, 0)
            .range(0, kU16Max)
            .persistent()
            .pdo_mappable();
    };
    od.add_object(0x60F6, "Current Control Parameter Set", kRecord);
    gain(0x60F6, 1, "Current Regulator P-Gain");
    gain(0x60F6, 2, "Current Regulator I-Gain");
    // 8.2.126 has no sub-index 3, and types the feed-forward factors INTEGER16 with the range
    // 0 ... 65 535 of an UNSIGNED16: they are UNSIGNED16 here, as in 0x60FB.
    od.add_object(0x60F9, "Velocity Control Parameter Set", kRecord);
    gain(0x60F9, 1, "Velocity Regulator P-Gain");
    gain(0x60F9, 2, "Velocity Regulator I-Gain");
    feed_forward(0x60F9, 4, "Velocity Feedforward Factor in Speed Regulator");
    feed_forward(0x60F9, 5, "Acceleration Feedforward Factor in Speed Regulator");
    od.add_object(0x60FB, "Position Control Parameter Set", kRecord);
    gain(0x60FB, 1, "Position Regulator P-Gain");
    gain(0x60FB, 2, "Position Regulator I-Gain");
    gain(0x60FB, 3, "Position Regulator D-Gain");
    feed_forward(0x60FB, 4, "Velocity Feed Forward Factor");
    feed_forward(0x60FB, 5, "Acceleration Feed Forward Factor");
    // 8.2.128: "-Maximal profile velocity ... Maximal profile velocity".
    add_var(od, 0x60FF, "Target Velocity", kI32, kRW, 0)
        .at_most(od, 0x607F, 0, /*symmetric=*/true)
        .pdo_mappable();
}

// 8.2.129 - 8.2.131
void add_motor_objects(canopen::ObjectDictionary& od) {
    // Table 8-125: 65535 (sinus incremental encoder 2) exists on the 70/10 and 50/5 only.
    add_var(od, 0x6402, "Motor Type", kU16, kRW, 10).one_of({1, 10, 11}).persistent();
    // 8.2.130: the number of entries reads 0x06 for sub-indices 1 - 5. Currents in mA for an
    // EPOS2 24/5; the maximal speed is bounded by table 8-126.
    od.add_object(0x6410, "Motor Data", kRecord);
    add_entry(od, 0x6410, 1, "Continuous Current Limit", kU16, kRW, 5000)
        .range(0, 5000)
        .persistent()
        .pdo_mappable();
    add_entry(od, 0x6410, 2, "Output Current Limit", kU16, kRW, 10'000)
        .range(0, 10'000)
        .persistent()
        .pdo_mappable();
    add_entry(od, 0x6410, 3, "Pole Pair Number", kU8, kRW, 1).range(1, 255).persistent();
    add_entry(od, 0x6410, 4, "Maximal Motor Speed", kU32, kRW, 25'000)
        .range(1, kU32Max)
        .persistent()
        .pdo_mappable();
    add_entry(od, 0x6410, 5, "Thermal Time Constant Winding", kU16, kRW, 40)
        .range(1, 5400)
        .persistent();
    // Profile position, profile velocity, homing, interpolated position and the six maxon modes.
    add_var(od, 0x6502, "Supported Drive Modes", kU32, kConst, 0x003F'0065);
}

// Table 8-119: the upper limit of 0x607F is the smaller of Maximal Motor Speed (0x6410 sub 4)
// and Gear Maximal Speed (0x2230 sub 3), the motor side's; with a gear (numerator not 0) the
// load side's, × denominator / numerator; in velocity units (0x608B). Checked at each write (a
// limit lowered later leaves the value as it is, like the other bounded ranges).
void bound_maximal_profile_velocity(canopen::ObjectDictionary& od) {
    Entry(*od.find(0x607F, 0)).rule([&od](std::span<const std::uint8_t> value) {
        const auto motor_side =
            std::min(od.get_as<std::uint32_t>(0x6410, 4), od.get_as<std::uint32_t>(0x2230, 3));
        const auto numerator = od.get_as<std::uint32_t>(0x2230, 1);
        const double limit_rpm =
            numerator == 0
                ? static_cast<double>(motor_side)
                : static_cast<double>(motor_side) * od.get_as<std::uint16_t>(0x2230, 2) / numerator;
        // 8.2.106: "The maximum value range also depends on Velocity Notation Index".
        const double limit = std::floor(limit_rpm / rpm_per_velocity_unit(od) + 1e-9);
        return canopen::decode<std::uint32_t>(value) > limit ? canopen::AbortCode::ValueTooHigh
                                                             : canopen::AbortCode::None;
    });
}

} // namespace

void add_profile_objects(canopen::ObjectDictionary& od) {
    add_device_control_objects(od);
    add_position_velocity_objects(od);
    add_profile_motion_objects(od);
    add_factor_group_objects(od);
    add_homing_interpolation_objects(od);
    add_control_parameter_objects(od);
    add_motor_objects(od);
    bound_maximal_profile_velocity(od);
}

} // namespace eposp::drives::epos2
