#pragma once

#include "eposp/service/link.hpp"

#include <cstdint>
#include <memory>
#include <string_view>

namespace eposp::device {

class EposP;

/// The protocol a service link speaks (docs/service-interface.md).
enum class ServiceProtocol {
    Rs232, ///< maxon serial v1: handshakes, Len-1
    Usb,   ///< maxon serial v2: 0x90 0x02 frames with byte stuffing
};
std::string_view to_string(ServiceProtocol protocol);

/// What a service port has done since it opened.
struct ServicePortCounters {
    std::uint64_t requests = 0;     ///< executed
    std::uint64_t answers = 0;      ///< sent back
    std::uint64_t frame_errors = 0; ///< dropped for a wrong CRC, stuffing, a timeout
    std::uint64_t refused_busy = 0; ///< v1 opcodes refused with 'F'; v2 requests over the queue
    std::uint64_t hang_ups = 0;     ///< hosts that went away
};

/// One service interface of the EPOS P (the RS-232 or the USB port): the bytes of its link are
/// framed by the protocol, each request is executed on the device (its own objects, or through
/// the gateway a node of its CAN ports) and answered. A frame that stalls longer than the frame
/// timeout 0x5005 is dropped and the port waits for the next one; a host that hangs up ends
/// what it started, and the port serves the next host.
///
/// The port and the device must outlive nothing of each other: destroy the port first.
class ServicePort {
public:
    /// On USB, how many requests may wait while one is executed; more are dropped.
    static constexpr std::size_t kMaxQueuedRequests = 16;

    ServicePort(EposP& device, std::unique_ptr<service::Link> link, ServiceProtocol protocol);
    ~ServicePort();
    ServicePort(const ServicePort&) = delete;
    ServicePort& operator=(const ServicePort&) = delete;

    ServiceProtocol protocol() const;
    const service::Link& link() const;
    ServicePortCounters counters() const;

private:
    class Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace eposp::device
