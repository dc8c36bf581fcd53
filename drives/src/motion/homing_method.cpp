#include "eposp/drives/motion/homing_method.hpp"

#include <array>

namespace eposp::drives::motion {

namespace {

struct MethodRow {
    HomingMethod method;
    HomingMethodTraits traits;
};

using enum HomingReference;

// EPOS2 FW spec 5.4.3: the reference each method searches, in which direction, and whether the
// index pulse after it is the home.
constexpr std::array<MethodRow, 16> kMethods{{
    {HomingMethod::CurrentThresholdNegative, {CurrentThreshold, -1, false}},
    {HomingMethod::CurrentThresholdPositive, {CurrentThreshold, +1, false}},
    {HomingMethod::CurrentThresholdNegativeIndex, {CurrentThreshold, -1, true}},
    {HomingMethod::CurrentThresholdPositiveIndex, {CurrentThreshold, +1, true}},
    {HomingMethod::NoHoming, {None, 0, false}},
    {HomingMethod::NegativeLimitSwitchIndex, {NegativeLimitSwitch, -1, true}},
    {HomingMethod::PositiveLimitSwitchIndex, {PositiveLimitSwitch, +1, true}},
    {HomingMethod::HomeSwitchPositiveIndex, {HomeSwitch, +1, true}},
    {HomingMethod::HomeSwitchNegativeIndex, {HomeSwitch, -1, true}},
    {HomingMethod::NegativeLimitSwitch, {NegativeLimitSwitch, -1, false}},
    {HomingMethod::PositiveLimitSwitch, {PositiveLimitSwitch, +1, false}},
    {HomingMethod::HomeSwitchPositive, {HomeSwitch, +1, false}},
    {HomingMethod::HomeSwitchNegative, {HomeSwitch, -1, false}},
    {HomingMethod::IndexNegative, {None, -1, true}},
    {HomingMethod::IndexPositive, {None, +1, true}},
    {HomingMethod::ActualPosition, {None, 0, false}},
}};

} // namespace

std::optional<HomingMethod> to_homing_method(std::int8_t code) {
    for (const MethodRow& row : kMethods) {
        if (static_cast<std::int8_t>(row.method) == code) {
            return row.method;
        }
    }
    return std::nullopt;
}

HomingMethodTraits traits(HomingMethod method) {
    for (const MethodRow& row : kMethods) {
        if (row.method == method) {
            return row.traits;
        }
    }
    return {}; // unreachable for a valid enumerator; no motion is the safe answer
}

} // namespace eposp::drives::motion
