#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/time.hpp"

#include <cstdint>
#include <functional>

namespace eposp::drives::escon2 {
class Escon2Drive;
}

namespace eposp::device {

class EposP;
class NetworkPort;

/// Where maxon's devices answer the same commands differently (docs/service-interface.md).
struct ServiceDialect {
    std::uint32_t unknown_command = 0; ///< an opcode the device does not serve
    std::uint32_t wrong_node = 0;      ///< a NodeId or network the device does not reach
    /// A ReadObject of a value longer than its 4 bytes.
    std::uint32_t segmented_expected = 0;
    /// A USB frame whose CRC is wrong is answered with 0x05040004; otherwise it is dropped.
    bool answers_crc_errors = false;
};

/// The parts of a device that its service interface reaches.
struct ServiceParts {
    canopen::ObjectDictionary& objects;
    ServiceDialect dialect;
    /// How long a frame may stall before the port drops it.
    std::function<core::Duration()> frame_timeout;
    /// Port 1 (internal) or 2 (external, the CAN port of the plain opcodes) of the gateway.
    /// Empty for a device without CAN (the ESCON2): it serves the object commands of NodeId 0
    /// only, and no other command.
    std::function<NetworkPort&(std::uint8_t port)> network_port;
};

/// The EPOS P's: its dictionary, its two CAN ports, the frame timeout 0x5005.
ServiceParts service_parts(EposP& device);
/// The ESCON2's (ESCON2 FW spec 5.1, 7.2): its dictionary, the abort codes of table 111.
ServiceParts service_parts(drives::escon2::Escon2Drive& drive);

} // namespace eposp::device
