#pragma once

// The parts of CiA 402 device control and the profile modes the axis driver uses (EPOS2
// firmware specification 3.2, table 3-4/3-5; 8.2.86, table 8-114).

#include <cstdint>

namespace eposp::plcopen::cia402 {

// Controlword commands (device control bits 0..3 and 7).
inline constexpr std::uint16_t kShutdown = 0x0006;
inline constexpr std::uint16_t kEnableOperation = 0x000F;
inline constexpr std::uint16_t kQuickStop = 0x0002;
inline constexpr std::uint16_t kFaultReset = 0x0080;

// Controlword bits of the profile modes.
inline constexpr std::uint16_t kNewSetpoint = 1U << 4;       ///< PPM; homing operation start in HMM
inline constexpr std::uint16_t kChangeImmediately = 1U << 5; ///< PPM
inline constexpr std::uint16_t kHalt = 1U << 8;

// Statusword bits of the modes.
inline constexpr std::uint16_t kTargetReached = 1U << 10;
inline constexpr std::uint16_t kSetpointAcknowledge = 1U << 12; ///< PPM
inline constexpr std::uint16_t kHomingAttained = 1U << 12;      ///< HMM
inline constexpr std::uint16_t kHomingError = 1U << 13;         ///< HMM

// Modes of operation 0x6060 / 0x6061.
inline constexpr std::int8_t kProfilePosition = 1;
inline constexpr std::int8_t kProfileVelocity = 3;
inline constexpr std::int8_t kHoming = 6;

/// Fault or Fault reaction active.
constexpr bool is_fault(std::uint16_t statusword) {
    return (statusword & 0x4F) == 0x08 || (statusword & 0x4F) == 0x0F;
}
/// Fault reaction active: the drive still runs its quick stop (table 3-4, x0xx 1111).
constexpr bool is_fault_reaction_active(std::uint16_t statusword) {
    return (statusword & 0x4F) == 0x0F;
}
constexpr bool is_switch_on_disabled(std::uint16_t statusword) {
    return (statusword & 0x4F) == 0x40;
}
constexpr bool is_operation_enabled(std::uint16_t statusword) {
    return (statusword & 0x6F) == 0x27;
}

} // namespace eposp::plcopen::cia402
