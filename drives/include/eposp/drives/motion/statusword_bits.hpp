#pragma once

#include <cstdint>

namespace eposp::drives::motion {

// EPOS2 FW spec 8.2.86, table 8-114: the statusword bits the operating modes own (the state bits
// are device_control.hpp's). One bit means different things in different modes.
inline constexpr std::uint16_t kTargetReachedBit = 1U << 10;       ///< PPM, PVM, HMM, IPM
inline constexpr std::uint16_t kInternalLimitActiveBit = 1U << 11; ///< every mode: I²t (5.14.1)
inline constexpr std::uint16_t kSetpointAcknowledgeBit = 1U << 12; ///< PPM
inline constexpr std::uint16_t kSpeedZeroBit = 1U << 12;           ///< PVM: speed is equal 0
inline constexpr std::uint16_t kHomingAttainedBit = 1U << 12;      ///< HMM
inline constexpr std::uint16_t kFollowingErrorBit = 1U << 13;      ///< PPM
inline constexpr std::uint16_t kHomingErrorBit = 1U << 13;         ///< HMM
inline constexpr std::uint16_t kPositionReferencedBit = 1U << 15;  ///< every mode

} // namespace eposp::drives::motion
