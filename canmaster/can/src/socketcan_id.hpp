#pragma once

#include <cstdint>

// Internal: the flag bits that SocketCAN's `can_id` carries next to the identifier
// (linux/can.h). candump logs and LINKTYPE_CAN_SOCKETCAN records use the same layout.
namespace eposp::can::socketcan {

inline constexpr std::uint32_t kExtendedFlag = 0x8000'0000; // CAN_EFF_FLAG
inline constexpr std::uint32_t kRemoteFlag = 0x4000'0000;   // CAN_RTR_FLAG
inline constexpr std::uint32_t kErrorFlag = 0x2000'0000;    // CAN_ERR_FLAG
inline constexpr std::uint32_t kIdMask = 0x1FFF'FFFF;       // CAN_EFF_MASK, also CAN_ERR_MASK
inline constexpr std::uint32_t kFlagMask = kExtendedFlag | kRemoteFlag | kErrorFlag;

} // namespace eposp::can::socketcan
