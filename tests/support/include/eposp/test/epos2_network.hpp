#pragma once

#include "eposp/can/virtual_bus.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"

#include <cstddef>
#include <memory>
#include <vector>

namespace eposp::test {

/// N simulated EPOS2s on one virtual bus in one process, node-IDs first_node_id, +1, …; the
/// caller connects its master to `bus`. Every drive gets `config` with its own node-ID and
/// serial number (and no parameter file).
struct Epos2Network {
    std::unique_ptr<can::VirtualBus> bus;
    std::vector<std::unique_ptr<can::VirtualPort>> ports;
    std::vector<std::unique_ptr<drives::epos2::Epos2Drive>> drives;
};
Epos2Network make_epos2_network(core::EventLoop& loop, std::size_t count,
                                const drives::epos2::Epos2DriveConfig& config, canopen::NodeId first_node_id = 1);

} // namespace eposp::test
