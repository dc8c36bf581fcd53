#include "eposp/device/fault_injector.hpp"

#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/drives/epos2/device_errors.hpp"
#include "severable_port.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::device {
namespace {

constexpr std::uint8_t kUnassigned = 255;
constexpr std::uint8_t kEpos2PdoCount = 4;         // EPOS2 FW spec 8.2.18 - 8.2.29
constexpr std::uint32_t kPdoInvalidBit = 1U << 31; // CiA 301 7.5.2.35
constexpr std::uint32_t kStandardIdMask = 0x7FF;

std::string describe(const NodeTarget& node) {
    return fmt::format("node {} on port {}", node.node, node.port);
}

std::optional<core::Error> refuse(std::string message) {
    return core::Error{std::move(message)};
}

std::optional<std::string> wrong_port(std::uint8_t port) {
    if (port == kInternalPort || port == kExternalPort) {
        return std::nullopt;
    }
    return fmt::format("port {}: the EPOS P has ports {} (internal) and {} (CAN)", port,
                       kInternalPort, kExternalPort);
}

} // namespace

core::Result<NodeTarget> FaultInjector::resolve(const FaultTarget& target) const {
    if (const auto* node = std::get_if<NodeTarget>(&target)) {
        if (const auto error = wrong_port(node->port)) {
            return core::Error{*error};
        }
        if (node->node < 1 || node->node > canopen::kMaxNodeId) {
            return core::Error{
                fmt::format("node {}: a node-ID is 1..{}", node->node, canopen::kMaxNodeId)};
        }
        return *node;
    }
    const std::uint8_t axis = std::get<AxisTarget>(target).axis;
    if (axis >= kAxisCount) {
        return core::Error{
            fmt::format("axis {}: the axis table has axes 0..{}", axis, kAxisCount - 1)};
    }
    // 10.36, table 30: 0 the internal EPOS2, 1..127 a node on port 2, 255 unassigned.
    const auto slave =
        device_.objects().get_as<std::uint8_t>(static_cast<std::uint16_t>(kAxisIndex + axis), 1);
    if (slave == kInternalSlave) {
        return NodeTarget{kInternalPort, 1}; // the internal EPOS2 is node 1 (DESIGN.md, "CAN")
    }
    if (slave > canopen::kMaxNodeId) {
        return core::Error{
            fmt::format("axis {} has no slave (0x{:04X} sub 1 = {}{})", axis, kAxisIndex + axis,
                        slave, slave == kUnassigned ? ", unassigned" : ", not a slave number")};
    }
    return NodeTarget{kExternalPort, slave};
}

core::Result<FaultInjector::SimulatedSlave>
FaultInjector::simulated(const FaultTarget& target) const {
    const core::Result<NodeTarget> node = resolve(target);
    if (!node) {
        return core::Error{node.error()};
    }
    if (node->port == kInternalPort && node->node == 1) {
        return SimulatedSlave{device_.internal_drive_.get(), device_.internal_drive_link_.get(),
                              *node};
    }
    if (node->port == kExternalPort) {
        for (std::size_t i = 0; i < device_.slaves_.size(); ++i) {
            if (device_.slaves_[i]->node().node_id() == node->node) {
                return SimulatedSlave{device_.slaves_[i].get(), device_.slave_links_[i].get(),
                                      *node};
            }
        }
    }
    const auto listed = device_.network_list(node->port).slaves;
    const bool external = std::ranges::any_of(listed, [&node](const manager::SlaveEntry& slave) {
        return slave.node_id == node->node && slave.assigned();
    });
    return core::Error{external
                           ? fmt::format("{} is a slave of another process or real hardware (kind "
                                         "external): faults inside it cannot be injected from here",
                                         describe(*node))
                           : fmt::format("no simulated EPOS2 is {}", describe(*node))};
}

void FaultInjector::inject(std::function<void()> fault) {
    device_.loop().post(std::move(fault));
}

std::optional<core::Error> FaultInjector::drop_heartbeat(const FaultTarget& target) {
    const auto slave = simulated(target);
    if (!slave) {
        return refuse(slave.error());
    }
    inject([link = slave->link] { link->set_cut(true); });
    return std::nullopt;
}

std::optional<core::Error> FaultInjector::restore_heartbeat(const FaultTarget& target) {
    const auto slave = simulated(target);
    if (!slave) {
        return refuse(slave.error());
    }
    inject([link = slave->link, drive = slave->drive] {
        if (link->cut()) {
            link->set_cut(false);
            drive->start(); // power-up: its boot-up message tells the manager to boot it again
        }
    });
    return std::nullopt;
}

std::optional<core::Error> FaultInjector::set_limit_switch(const FaultTarget& target,
                                                           drives::epos2::LimitSwitch which,
                                                           bool pressed) {
    const auto slave = simulated(target);
    if (!slave) {
        return refuse(slave.error());
    }
    inject([drive = slave->drive, which, pressed] { drive->hold_limit_switch(which, pressed); });
    return std::nullopt;
}

std::optional<core::Error> FaultInjector::raise_drive_error(const FaultTarget& target,
                                                            std::uint16_t code) {
    const auto errors = drives::epos2::device_errors();
    if (std::ranges::none_of(errors, [code](const drives::epos2::DeviceError& error) {
            return error.code == code;
        })) {
        return refuse(
            fmt::format("0x{:04X} is not an EPOS2 error code (EPOS2 FW spec table 4-11)", code));
    }
    const auto slave = simulated(target);
    if (!slave) {
        return refuse(slave.error());
    }
    inject([drive = slave->drive, code] { drive->raise_device_error(code); });
    return std::nullopt;
}

std::optional<core::Error> FaultInjector::corrupt_pdo(const FaultTarget& target,
                                                      PdoDirection direction, std::uint8_t number,
                                                      PdoFault fault, std::uint32_t frames) {
    if (number < 1 || number > kEpos2PdoCount) {
        return refuse(fmt::format("PDO {}: an EPOS2 has PDOs 1..{}", number, kEpos2PdoCount));
    }
    const auto slave = simulated(target);
    if (!slave) {
        return refuse(slave.error());
    }
    const auto index = static_cast<std::uint16_t>(
        (direction == PdoDirection::Rpdo ? 0x1400 : 0x1800) + number - 1);
    const auto cob_id = slave->drive->objects().get_as<std::uint32_t>(index, 1);
    const char* name = direction == PdoDirection::Rpdo ? "RPDO" : "TPDO";
    if ((cob_id & kPdoInvalidBit) != 0) {
        return refuse(fmt::format("{} {} of {} is not valid (0x{:04X} sub 1 = 0x{:08X})", name,
                                  number, describe(slave->where), index, cob_id));
    }
    return corrupt_frames(slave->where.port, cob_id & kStandardIdMask, fault, frames);
}

std::optional<core::Error> FaultInjector::corrupt_frames(std::uint8_t port, std::uint32_t cob_id,
                                                         PdoFault fault, std::uint32_t frames) {
    if (auto error = wrong_port(port)) {
        return refuse(std::move(*error));
    }
    if (cob_id > kStandardIdMask) {
        return refuse(fmt::format("COB-ID 0x{:X}: an 11-bit identifier is 0..0x7FF", cob_id));
    }
    if (frames == 0) {
        return refuse("a frame fault takes at least one frame");
    }
    can::VirtualBus& bus = port == kInternalPort ? device_.internal_bus() : device_.external_bus();
    inject([&bus, cob_id, fault, frames] {
        const auto matches = [cob_id](const can::Frame& frame) {
            return frame.id == cob_id && !frame.extended && !frame.remote;
        };
        if (fault == PdoFault::Drop) {
            bus.drop_frames(matches, frames);
        } else {
            bus.shorten_frames(matches, frames);
        }
    });
    return std::nullopt;
}

} // namespace eposp::device
