#pragma once

#include <cstdint>
#include <string_view>

namespace eposp::manager {

/// Why a slave failed its boot-up: the CAN master error codes of EPOS P firmware specification
/// table 1 that the configuration manager reports.
enum class BootError : std::uint16_t {
    DeviceType = 0x6381,
    VendorId = 0x6382,
    ProductCode = 0x6383,
    RevisionNumber = 0x6384,
    SerialNumber = 0x6385,
    ConfigurationDateTime = 0x6386, ///< also: the configuration could not be written
    ErrorControl = 0x6387,          ///< no heartbeat received
    NotSlave = 0x6388,              ///< a mandatory node is not assigned as a slave
    NoAnswer = 0x8182,              ///< the node does not answer / is not present
};

/// Table 1's description ("Vendor-Id Error").
std::string_view describe(BootError error);

} // namespace eposp::manager
