#pragma once

#include <cstdint>

namespace eposp::drives::plant {

// The control parameter sets as the object dictionary holds them (EPOS2 FW spec 8.2.125-127).
// The spec gives only their integer ranges, not their scaling; this model fixes one scaling per
// gain (documented next to each field) so that typical maxon motors tune to values well inside
// 0…32767. Angles are motor-shaft radians, so the gains do not depend on the encoder.

/// 0x60F6 Current Control Parameter Set.
struct CurrentControlParameterSet {
    std::int16_t p_gain = 0; ///< sub 1, mV/A
    std::int16_t i_gain = 0; ///< sub 2, mV/(A·ms)
};

/// 0x60F9 Velocity Control Parameter Set (sub 3 does not exist).
struct VelocityControlParameterSet {
    std::int16_t p_gain = 0;                     ///< sub 1, 0.1 mA·s/rad
    std::int16_t i_gain = 0;                     ///< sub 2, mA/rad
    std::uint16_t velocity_feed_forward = 0;     ///< sub 4, 0.1 mA·s/rad
    std::uint16_t acceleration_feed_forward = 0; ///< sub 5, µA·s²/rad
};

/// 0x60FB Position Control Parameter Set.
struct PositionControlParameterSet {
    std::int16_t p_gain = 0;                     ///< sub 1, mA/rad
    std::int16_t i_gain = 0;                     ///< sub 2, mA/(rad·s)
    std::int16_t d_gain = 0;                     ///< sub 3, 0.1 mA·s/rad
    std::uint16_t velocity_feed_forward = 0;     ///< sub 4, 0.1 mA·s/rad
    std::uint16_t acceleration_feed_forward = 0; ///< sub 5, µA·s²/rad
};

/// The same gains in SI units, as the control laws use them.
struct CurrentGains {
    double kp = 0; ///< V/A
    double ki = 0; ///< V/(A·s)
};

struct VelocityGains {
    double kp = 0;                        ///< A·s/rad
    double ki = 0;                        ///< A/rad
    double velocity_feed_forward = 0;     ///< A·s/rad
    double acceleration_feed_forward = 0; ///< A·s²/rad
};

struct PositionGains {
    double kp = 0;                        ///< A/rad
    double ki = 0;                        ///< A/(rad·s)
    double kd = 0;                        ///< A·s/rad
    double velocity_feed_forward = 0;     ///< A·s/rad
    double acceleration_feed_forward = 0; ///< A·s²/rad
};

CurrentGains to_si(const CurrentControlParameterSet& set);
VelocityGains to_si(const VelocityControlParameterSet& set);
PositionGains to_si(const PositionControlParameterSet& set);

/// The nearest parameter sets (saturated to their types): the dictionary's defaults for gains
/// given in SI units.
CurrentControlParameterSet to_parameter_set(const CurrentGains& gains);
VelocityControlParameterSet to_parameter_set(const VelocityGains& gains);
PositionControlParameterSet to_parameter_set(const PositionGains& gains);

} // namespace eposp::drives::plant
