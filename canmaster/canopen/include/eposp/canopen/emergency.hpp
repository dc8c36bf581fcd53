#pragma once

#include <cstdint>
#include <functional>

namespace eposp::canopen {

/// What a service calls when it detects an error that the node signals by EMCY; the node that
/// composes the services wires it to its EmcyProducer, with the error register bits its device
/// table gives the code (EPOS2 FW spec table 4-11).
using EmergencyCallback = std::function<void(std::uint16_t error_code)>;

// Emergency error codes the communication services raise (CiA 301 7.2.7.1).
inline constexpr std::uint16_t kEmcyNoError = 0x0000; ///< error reset or no error
/// Life guarding or heartbeat consumer timeout (EPOS2 FW spec 4.2.16).
inline constexpr std::uint16_t kEmcyLifeGuardOrHeartbeat = 0x8130;
inline constexpr std::uint16_t kEmcySyncDataLength = 0x8240; ///< unexpected SYNC data length

} // namespace eposp::canopen
