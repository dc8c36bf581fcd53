#pragma once

#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "object_access.hpp"

#include <memory>

namespace eposp::device {

class NetworkPort;

/// The objects of a node on one of the EPOS P's CAN ports, through its gateway: each access is
/// one SDO transfer of the whole value (the SDO client picks expedited or segmented).
class GatewayAccess final : public ObjectAccess {
public:
    /// The longest value a segmented write through the gateway may announce.
    static constexpr std::uint32_t kMaxValue = 1U << 20;

    GatewayAccess(NetworkPort& port, canopen::NodeId node) : port_(port), node_(node) {}
    ~GatewayAccess() override;
    GatewayAccess(const GatewayAccess&) = delete;
    GatewayAccess& operator=(const GatewayAccess&) = delete;

    void upload(std::uint16_t index, std::uint8_t sub_index, Uploaded done) override;
    /// The 4 bytes of a WriteObject go without a size: the node's object decides how many it
    /// takes, as it would from the device itself.
    void download(std::uint16_t index, std::uint8_t sub_index, canopen::Bytes value, bool sized,
                  Downloaded done) override;
    canopen::AbortCode check_write_size(std::uint16_t index, std::uint8_t sub_index,
                                        std::uint32_t length) const override;
    /// Nothing to tell: the node's value was only ever in the server's buffer.
    void write_aborted(std::uint16_t, std::uint8_t, canopen::AbortCode) override {}
    void cancel() override;

private:
    NetworkPort& port_;
    canopen::NodeId node_;
    canopen::SdoRequestId request_{};
    /// The SDO callbacks check it, so that none runs after a cancel or after this died.
    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

} // namespace eposp::device
