#include "eposp/test/epos2_network.hpp"

#include <string>

namespace eposp::test {

Epos2Network make_epos2_network(core::EventLoop& loop, std::size_t count,
                                const drives::epos2::Epos2DriveConfig& config, canopen::NodeId first_node_id) {
    Epos2Network network;
    network.bus = std::make_unique<can::VirtualBus>(loop);
    for (std::size_t n = 0; n < count; ++n) {
        drives::epos2::Epos2DriveConfig drive_config = config;
        drive_config.dictionary.node_id = static_cast<canopen::NodeId>(first_node_id + n);
        drive_config.dictionary.serial_number = config.dictionary.serial_number + n;
        drive_config.dictionary.parameter_file.clear();
        network.ports.push_back(
            network.bus->connect("epos2-" + std::to_string(drive_config.dictionary.node_id)));
        network.drives.push_back(
            std::make_unique<drives::epos2::Epos2Drive>(loop, *network.ports.back(), drive_config));
        network.drives.back()->start();
    }
    return network;
}

} // namespace eposp::test
