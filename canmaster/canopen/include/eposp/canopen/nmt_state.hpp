#pragma once

#include <cstdint>
#include <string_view>

namespace eposp::canopen {

/// The NMT states of a slave (CiA 301 7.3.2.2), by the code its heartbeat and node-guarding
/// replies carry (7.2.8.3.2.1).
enum class NmtState : std::uint8_t {
    Initialising = 0x00, ///< boot-up: the state of the boot-up message
    Stopped = 0x04,
    Operational = 0x05,
    PreOperational = 0x7F,
};
std::string_view to_string(NmtState state);

/// A node-ID as CiA 301 allows it: 1..127 (0 is the broadcast / unconfigured, 255 LSS).
using NodeId = std::uint8_t;

} // namespace eposp::canopen
