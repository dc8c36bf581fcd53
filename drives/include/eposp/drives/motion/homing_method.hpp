#pragma once

#include <cstdint>
#include <optional>

namespace eposp::drives::motion {

/// Homing Method 0x6098, EPOS2 FW spec table 8-121; the values are the dictionary's codes.
enum class HomingMethod : std::int8_t {
    CurrentThresholdNegative = -4,      ///< 5.4.3.14
    CurrentThresholdPositive = -3,      ///< 5.4.3.13
    CurrentThresholdNegativeIndex = -2, ///< 5.4.3.12
    CurrentThresholdPositiveIndex = -1, ///< 5.4.3.11
    NoHoming = 0,                       ///< no homing operation required
    NegativeLimitSwitchIndex = 1,       ///< 5.4.3.1
    PositiveLimitSwitchIndex = 2,       ///< 5.4.3.2
    HomeSwitchPositiveIndex = 7,        ///< 5.4.3.3
    HomeSwitchNegativeIndex = 11,       ///< 5.4.3.4
    NegativeLimitSwitch = 17,           ///< 5.4.3.5
    PositiveLimitSwitch = 18,           ///< 5.4.3.6
    HomeSwitchPositive = 23,            ///< 5.4.3.7
    HomeSwitchNegative = 27,            ///< 5.4.3.8
    IndexNegative = 33,                 ///< 5.4.3.9
    IndexPositive = 34,                 ///< 5.4.3.9
    ActualPosition = 35,                ///< 5.4.3.10
};

/// The method of a dictionary code, or nothing for a code table 8-121 does not list.
std::optional<HomingMethod> to_homing_method(std::int8_t code);

/// What the first, fast search of a method looks for.
enum class HomingReference {
    None, ///< no search: index-only methods go straight to the index, 0 and 35 do not move
    NegativeLimitSwitch,
    PositiveLimitSwitch,
    HomeSwitch,
    CurrentThreshold, ///< a mechanical end stop, detected by the current (0x2080)
};

/// A method reduced to the few facts its sequence depends on.
struct HomingMethodTraits {
    HomingReference reference = HomingReference::None;
    /// +1 or −1: the direction of the search for the reference (index-only methods: for the
    /// index); 0 for the methods that do not move.
    int search_direction = 0;
    /// The home is the next index pulse after the reference, not the reference itself.
    bool uses_index = false;

    friend bool operator==(const HomingMethodTraits&, const HomingMethodTraits&) = default;
};

HomingMethodTraits traits(HomingMethod method);

} // namespace eposp::drives::motion
