#pragma once

#include <cstdint>
#include <string_view>

namespace eposp::plcopen {

/// The PLCopen axis state diagram (Motion Control Part 1, 3.1), numbered as MC_ReadAxisState
/// reports it in its State output.
enum class AxisState : std::uint8_t {
    Disabled = 0,
    Standstill = 1,
    Homing = 2,
    DiscreteMotion = 3,
    ContinuousMotion = 4,
    Stopping = 5,
    ErrorStop = 6,
};

std::string_view name(AxisState state);

} // namespace eposp::plcopen
