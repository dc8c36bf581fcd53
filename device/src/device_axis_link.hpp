#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/plcopen/axis_link.hpp"
#include "eposp/vm/process_image.hpp"
#include "network_port.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace eposp::device {

/// plcopen's axis link on the EPOS P's manager (DESIGN.md, "Seams"): axis n is the slave that
/// 0x5280 + n sub 1 assigns (0: the internal EPOS2 on port 1, 1..127: that node on port 2). Its
/// statusword is 0x5280 + n sub 2; its position actual value, controlword and target position
/// are the axis' process image channels (AxisChannels), which the axis PDOs of the network file
/// carry. SDO transfers go through the port's SDO client; samples() counts
/// the port's SYNCs, after which the PLC task of the cycle runs with the TPDOs in. An axis is
/// lost when its slave is not booted (a failed boot, a lost heartbeat) or, once its statusword
/// has come by PDO, when none came for 10 SYNCs.
class DeviceAxisLink : public plcopen::AxisLink {
public:
    /// `ports` gives the NetworkPort of port 1 or 2; all must outlive the link.
    DeviceAxisLink(canopen::ObjectDictionary& od, vm::ProcessImage& image,
                   std::function<NetworkPort&(std::uint8_t port)> ports);
    ~DeviceAxisLink() override;
    DeviceAxisLink(const DeviceAxisLink&) = delete;
    DeviceAxisLink& operator=(const DeviceAxisLink&) = delete;

    plcopen::AxisPresence presence(plcopen::AxisNumber axis) const override;
    std::uint16_t statusword(plcopen::AxisNumber axis) const override;
    std::int32_t actual_position(plcopen::AxisNumber axis) const override;
    std::uint32_t samples(plcopen::AxisNumber axis) const override;
    void set_controlword(plcopen::AxisNumber axis, std::uint16_t controlword) override;
    void set_target_position(plcopen::AxisNumber axis, std::int32_t position) override;
    void read(plcopen::AxisNumber axis, std::uint16_t index, std::uint8_t sub_index,
              plcopen::SdoDone done) override;
    void write(plcopen::AxisNumber axis, std::uint16_t index, std::uint8_t sub_index,
               std::uint32_t value, std::uint8_t size, plcopen::SdoDone done) override;
    void read(plcopen::NodeAddress node, std::uint16_t index, std::uint8_t sub_index,
              plcopen::SdoDone done) override;
    void write(plcopen::NodeAddress node, std::uint16_t index, std::uint8_t sub_index,
               std::uint32_t value, std::uint8_t size, plcopen::SdoDone done) override;
    bool send_nmt(std::uint8_t port, std::uint8_t node, std::uint8_t command) override;

private:
    struct Slave {
        std::uint8_t port = 0;
        canopen::NodeId node = 0;
    };
    /// The slave 0x5280 + axis sub 1 assigns, if any.
    std::optional<Slave> slave(plcopen::AxisNumber axis) const;
    /// Tells `done` of `code` from the loop, as a transfer would (never from inside a call).
    void reply_later(plcopen::SdoDone done, plcopen::SdoReply reply);

    canopen::ObjectDictionary& od_;
    vm::ProcessImage& image_;
    std::function<NetworkPort&(std::uint8_t port)> ports_;
    std::array<std::uint32_t, 3> syncs_{}; ///< by port code
    /// syncs_ of the axis' port when its statusword last arrived; none before the first.
    std::array<std::optional<std::uint32_t>, plcopen::kAxisCount> last_statusword_{};
    std::vector<canopen::ObjectDictionary::ListenerId> listeners_;
};

} // namespace eposp::device
