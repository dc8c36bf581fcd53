#include "device_axis_link.hpp"

#include "eposp/device/axis_process_data.hpp"
#include "eposp/device/epos_p_dictionary.hpp"

#include <algorithm>
#include <cstring>

namespace eposp::device {

namespace {

constexpr std::uint16_t kAxisTable = 0x5280;
constexpr std::uint8_t kUnassigned = 255;
/// SYNCs without a new statusword after which an axis whose statusword came by PDO is lost:
/// its slave still sends its heartbeat, but its TPDOs stopped (an NMT stop, a lost frame ID).
constexpr std::uint32_t kMissedSyncs = 10;

template <typename T>
T entry_value(vm::ProcessImage& image, std::uint16_t index, std::uint8_t sub_index) {
    T value{};
    if (const auto bytes = image.entry(index, sub_index)) {
        std::memcpy(&value, bytes->data(), sizeof(T));
    }
    return value;
}

template <typename T>
void set_entry(vm::ProcessImage& image, std::uint16_t index, std::uint8_t sub_index, T value) {
    if (const auto bytes = image.entry(index, sub_index)) {
        std::memcpy(bytes->data(), &value, sizeof(T));
    }
}

/// A slave of port 1 or 2 (1..127).
bool on_a_bus(plcopen::NodeAddress node) {
    return (node.port == kInternalPort || node.port == kExternalPort) && node.node >= 1 &&
           node.node <= 127;
}

} // namespace

DeviceAxisLink::DeviceAxisLink(canopen::ObjectDictionary& od, vm::ProcessImage& image,
                               std::function<NetworkPort&(std::uint8_t port)> ports)
    : od_(od), image_(image), ports_(std::move(ports)) {
    for (const std::uint8_t port : {kInternalPort, kExternalPort}) {
        ports_(port).on_sync([this, port] { ++syncs_[port]; });
    }
    for (plcopen::AxisNumber axis = 0; axis < plcopen::kAxisCount; ++axis) {
        listeners_.push_back(
            od_.on_change(kAxisTable + axis, [this, axis](std::uint16_t, std::uint8_t sub_index) {
                const auto assigned = slave(axis);
                if (sub_index == 2 && assigned) {
                    last_statusword_[axis] = syncs_[assigned->port];
                }
            }));
    }
}

DeviceAxisLink::~DeviceAxisLink() {
    for (const auto id : listeners_) {
        od_.remove_listener(id);
    }
}

std::optional<DeviceAxisLink::Slave> DeviceAxisLink::slave(plcopen::AxisNumber axis) const {
    if (axis >= plcopen::kAxisCount) {
        return std::nullopt;
    }
    const auto number = od_.get_as<std::uint8_t>(kAxisTable + axis, 1);
    if (number == kUnassigned || number > 127) {
        return std::nullopt;
    }
    return number == 0 ? Slave{kInternalPort, 1} : Slave{kExternalPort, number};
}

plcopen::AxisPresence DeviceAxisLink::presence(plcopen::AxisNumber axis) const {
    const auto assigned = slave(axis);
    if (!assigned) {
        return plcopen::AxisPresence::Unassigned;
    }
    const auto& last = last_statusword_[axis];
    const bool pdos_stopped = last && syncs_[assigned->port] - *last > kMissedSyncs;
    return ports_(assigned->port).network().booted(assigned->node) && !pdos_stopped
               ? plcopen::AxisPresence::Ready
               : plcopen::AxisPresence::Lost;
}

std::uint16_t DeviceAxisLink::statusword(plcopen::AxisNumber axis) const {
    return axis < plcopen::kAxisCount ? od_.get_as<std::uint16_t>(kAxisTable + axis, 2) : 0;
}

std::int32_t DeviceAxisLink::actual_position(plcopen::AxisNumber axis) const {
    if (axis >= plcopen::kAxisCount) {
        return 0;
    }
    const ImageEntry entry = AxisChannels::of(axis).actual_position;
    return entry_value<std::int32_t>(image_, entry.index, entry.sub_index);
}

std::uint32_t DeviceAxisLink::samples(plcopen::AxisNumber axis) const {
    const auto assigned = slave(axis);
    return assigned ? syncs_[assigned->port] : 0;
}

void DeviceAxisLink::set_controlword(plcopen::AxisNumber axis, std::uint16_t controlword) {
    if (axis < plcopen::kAxisCount) {
        const ImageEntry entry = AxisChannels::of(axis).controlword;
        set_entry(image_, entry.index, entry.sub_index, controlword);
    }
}

void DeviceAxisLink::set_target_position(plcopen::AxisNumber axis, std::int32_t position) {
    if (axis < plcopen::kAxisCount) {
        const ImageEntry entry = AxisChannels::of(axis).target_position;
        set_entry(image_, entry.index, entry.sub_index, position);
    }
}

void DeviceAxisLink::read(plcopen::AxisNumber axis, std::uint16_t index, std::uint8_t sub_index,
                          plcopen::SdoDone done) {
    const auto assigned = slave(axis);
    if (!assigned) {
        reply_later(std::move(done),
                    {.abort_code = static_cast<std::uint32_t>(canopen::AbortCode::GeneralError)});
        return;
    }
    read(plcopen::NodeAddress{assigned->port, assigned->node}, index, sub_index, std::move(done));
}

void DeviceAxisLink::read(plcopen::NodeAddress node, std::uint16_t index, std::uint8_t sub_index,
                          plcopen::SdoDone done) {
    const auto reply_with = [](canopen::AbortCode code, const canopen::Bytes& value) {
        plcopen::SdoReply reply{.abort_code = static_cast<std::uint32_t>(code)};
        for (std::size_t i = 0; i < value.size() && i < 4; ++i) {
            reply.value |= static_cast<std::uint32_t>(value[i]) << (8 * i);
        }
        reply.size = static_cast<std::uint8_t>(std::min<std::size_t>(value.size(), 4));
        return reply;
    };
    if (node.port == 0 && node.node == 0) { // the EPOS P's own dictionary
        canopen::Bytes value;
        const canopen::AbortCode code = od_.read(index, sub_index, value);
        reply_later(std::move(done), reply_with(code, value));
        return;
    }
    if (!on_a_bus(node)) {
        reply_later(std::move(done),
                    {.abort_code = static_cast<std::uint32_t>(canopen::AbortCode::GeneralError)});
        return;
    }
    ports_(node.port).sdo().upload(
        node.node, index, sub_index,
        [done = std::move(done), reply_with](canopen::AbortCode code, const canopen::Bytes& value) {
            done(reply_with(code, value));
        });
}

void DeviceAxisLink::write(plcopen::AxisNumber axis, std::uint16_t index, std::uint8_t sub_index,
                           std::uint32_t value, std::uint8_t size, plcopen::SdoDone done) {
    const auto assigned = slave(axis);
    if (!assigned) {
        reply_later(std::move(done),
                    {.abort_code = static_cast<std::uint32_t>(canopen::AbortCode::GeneralError)});
        return;
    }
    write(plcopen::NodeAddress{assigned->port, assigned->node}, index, sub_index, value, size,
          std::move(done));
}

void DeviceAxisLink::write(plcopen::NodeAddress node, std::uint16_t index, std::uint8_t sub_index,
                           std::uint32_t value, std::uint8_t size, plcopen::SdoDone done) {
    canopen::Bytes bytes(size);
    for (std::uint8_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(value >> (8 * i));
    }
    if (node.port == 0 && node.node == 0) {
        const canopen::AbortCode code = od_.write(index, sub_index, bytes);
        reply_later(std::move(done), {.abort_code = static_cast<std::uint32_t>(code)});
        return;
    }
    if (!on_a_bus(node)) {
        reply_later(std::move(done),
                    {.abort_code = static_cast<std::uint32_t>(canopen::AbortCode::GeneralError)});
        return;
    }
    ports_(node.port).sdo().download(node.node, index, sub_index, std::move(bytes),
                                     [done = std::move(done)](canopen::AbortCode code) {
                                         done({.abort_code = static_cast<std::uint32_t>(code)});
                                     });
}

bool DeviceAxisLink::send_nmt(std::uint8_t port, std::uint8_t node, std::uint8_t command) {
    using canopen::NmtCommand;
    const auto known = {NmtCommand::Start, NmtCommand::Stop, NmtCommand::EnterPreOperational,
                        NmtCommand::ResetNode, NmtCommand::ResetCommunication};
    if ((port != kInternalPort && port != kExternalPort) || node > 127 ||
        std::ranges::find(known, static_cast<NmtCommand>(command)) == known.end()) {
        return false;
    }
    ports_(port).nmt().send(static_cast<NmtCommand>(command), node);
    return true;
}

void DeviceAxisLink::reply_later(plcopen::SdoDone done, plcopen::SdoReply reply) {
    ports_(kInternalPort).loop().post([done = std::move(done), reply] { done(reply); });
}

} // namespace eposp::device
