#pragma once

// The values a machine file may give (docs/epos2.md, "The machine file"), in the file's units.
#include <cstdint>
#include <limits>
#include <string_view>

namespace eposp::drives::plant::axis_file_limits {

/// A physical quantity: finite and inside a plausible range for the motors, gearheads and loads
/// an EPOS2 drives (maxon's catalogue with a wide margin), so that a typing error (a unit
/// prefix off by 10^6, `.inf`) is refused instead of making the model meaningless.
struct Quantity {
    double low;
    double high;
    std::string_view unit;
};

inline constexpr Quantity kTerminalResistance{0.001, 1000, "Ω"};
inline constexpr Quantity kTerminalInductance{0.001, 1000, "mH"};
inline constexpr Quantity kTorqueConstant{0.1, 10'000, "mN·m/A"};
inline constexpr Quantity kSpeedConstant{1, 100'000, "rpm/V"};
inline constexpr Quantity kRotorInertia{0.001, 100'000, "g·cm²"};
inline constexpr Quantity kGearRatio{0.1, 10'000, ""};
inline constexpr Quantity kGearEfficiency{0.01, 1, ""};
inline constexpr Quantity kLoadInertia{0, 1e9, "g·cm²"};
inline constexpr Quantity kViscousFriction{0, 100, "N·m·s/rad"};
inline constexpr Quantity kCoulombFriction{0, 100'000, "mN·m"};
inline constexpr Quantity kSupplyVoltage{1, 100, "V"};
inline constexpr Quantity kSupplyLimit{0, 100, "V"};
inline constexpr Quantity kMaxDuty{0.01, 1, ""};
inline constexpr Quantity kOvercurrent{0.1, 100, "A"};

/// A value that becomes the default of a dictionary entry (write_axis_defaults): the value range
/// an SDO write of that entry has (EPOS2 FW spec 8.2.74, 8.2.125 - 8.2.127, 8.2.130 for an EPOS2
/// 24/5). tests/drives/plant_axis_file_test.cpp checks them against the dictionary.
struct DictionaryValue {
    std::uint16_t index;
    std::uint8_t sub;
    std::int64_t low;
    std::int64_t high;
};

inline constexpr DictionaryValue kEncoderPulses{0x2210, 1, 16, 2'500'000};
inline constexpr DictionaryValue kCurrentP{0x60F6, 1, 0, 32'767};
inline constexpr DictionaryValue kCurrentI{0x60F6, 2, 0, 32'767};
inline constexpr DictionaryValue kVelocityP{0x60F9, 1, 0, 32'767};
inline constexpr DictionaryValue kVelocityI{0x60F9, 2, 0, 32'767};
inline constexpr DictionaryValue kVelocityFeedForward{0x60F9, 4, 0, 65'535};
inline constexpr DictionaryValue kVelocityAccelerationFeedForward{0x60F9, 5, 0, 65'535};
inline constexpr DictionaryValue kPositionP{0x60FB, 1, 0, 32'767};
inline constexpr DictionaryValue kPositionI{0x60FB, 2, 0, 32'767};
inline constexpr DictionaryValue kPositionD{0x60FB, 3, 0, 32'767};
inline constexpr DictionaryValue kPositionFeedForward{0x60FB, 4, 0, 65'535};
inline constexpr DictionaryValue kPositionAccelerationFeedForward{0x60FB, 5, 0, 65'535};
inline constexpr DictionaryValue kOutputCurrentLimit{0x6410, 2, 0, 10'000}; ///< mA
inline constexpr DictionaryValue kPolePairs{0x6410, 3, 1, 255};

/// Switch positions are quadcounts of Position Actual Value 0x6064 (INTEGER32); a home cam has a
/// length of at least one count.
inline constexpr std::int64_t kPositionLow = std::numeric_limits<std::int32_t>::min();
inline constexpr std::int64_t kPositionHigh = std::numeric_limits<std::int32_t>::max();

} // namespace eposp::drives::plant::axis_file_limits
