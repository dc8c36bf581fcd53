#pragma once

#include <cstdint>

namespace eposp::drives::motion {

// EPOS2 FW spec table 4-11: the error codes the motion layer detects. All are "f" errors: their
// reaction follows the Fault Reaction Option Code 0x605E.
inline constexpr std::uint16_t kFollowingErrorCode = 0x8611;             ///< 4.2.22
inline constexpr std::uint16_t kNegativeLimitSwitchErrorCode = 0xFF06;   ///< 4.2.27
inline constexpr std::uint16_t kPositiveLimitSwitchErrorCode = 0xFF07;   ///< 4.2.28
inline constexpr std::uint16_t kSoftwarePositionLimitErrorCode = 0xFF09; ///< 4.2.30

} // namespace eposp::drives::motion
