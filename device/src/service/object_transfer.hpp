#pragma once

#include "eposp/canopen/sdo_client.hpp"
#include "eposp/service/commands.hpp"
#include "service_target.hpp"

#include <functional>
#include <memory>
#include <optional>

namespace eposp::device {

/// The object commands of one service link (maxon EPOS2 communication guide): ReadObject and
/// WriteObject of up to 4 bytes, and segmented transfers of any size in segments of up to 63
/// bytes, on the controller's dictionary or, through the gateway, by SDO on a node of one of
/// its CAN ports. A link runs one segmented transfer at a time; a new initiate ends the one
/// before. A gateway transfer moves the whole value by SDO (the SDO client picks expedited or
/// segmented): an initiated read fetches it before it answers, a segmented write sends it once
/// the last segment is in.
///
/// Every command completes by its callback exactly once, possibly at once; a gateway request
/// in flight when the link is abandoned, or the object dies, never completes.
class ObjectTransfer {
public:
    using Done = std::function<void(service::Answer answer)>;
    /// The longest value a segmented write through the gateway may announce.
    static constexpr std::uint32_t kMaxGatewayValue = 1U << 20;

    explicit ObjectTransfer(const ServiceParts& parts);
    ~ObjectTransfer();
    ObjectTransfer(const ObjectTransfer&) = delete;
    ObjectTransfer& operator=(const ObjectTransfer&) = delete;

    void read(const service::ReadObject& request, Done done);
    void write(const service::WriteObject& request, Done done);
    void initiate_read(const service::InitiateSegmentedRead& request, Done done);
    void initiate_write(const service::InitiateSegmentedWrite& request, Done done);
    void read_segment(const service::SegmentRead& request, Done done);
    void write_segment(const service::SegmentWrite& request, Done done);
    /// The host went away: the segmented transfer ends, a gateway request is cancelled.
    void abandon();

private:
    using Uploaded = std::function<void(std::uint32_t error, canopen::Bytes value)>;
    using Downloaded = std::function<void(std::uint32_t error)>;
    struct Segmented;

    void upload(const ServiceTarget& target, std::uint16_t index, std::uint8_t sub_index,
                Uploaded done);
    void download(const ServiceTarget& target, std::uint16_t index, std::uint8_t sub_index,
                  canopen::Bytes value, bool sized, Downloaded done);
    void cancel_gateway_request();
    /// Ends the segmented transfer; an unfinished write to the controller's own object tells it
    /// why (ObjectDictionary::write_aborted).
    void end_segmented(canopen::AbortCode reason);

    const ServiceParts& parts_;
    std::unique_ptr<Segmented> segmented_;
    /// The gateway request in flight, to cancel when the link goes.
    canopen::SdoRequestId gateway_request_{};
    NetworkPort* gateway_port_ = nullptr;
    /// Gateway callbacks check it, so that none runs after this object died.
    std::shared_ptr<bool> alive_ = std::make_shared<bool>(true);
};

} // namespace eposp::device
