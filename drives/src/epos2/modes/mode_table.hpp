#pragma once

#include "eposp/drives/epos2/epos2_drive.hpp"
#include "mode_behaviour.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

namespace eposp::drives::epos2 {

/// 8.2.90, table 8-118: the mode a value of 0x6060 selects (none for a value the table lacks).
std::optional<OperatingMode> simulated_mode(std::int8_t modes_of_operation);

/// The behaviour of a simulated mode.
std::unique_ptr<ModeBehaviour> make_mode_behaviour(OperatingMode mode, ModeServices& services);

/// The set values of the modes, whose writes the drive passes to the mode running: the target
/// velocity of PVM, and IPM's data record and buffer command (5.5).
inline constexpr std::array<std::uint16_t, 3> kSetValueObjects{0x60FF, 0x20C1, 0x60C4};

} // namespace eposp::drives::epos2
