#pragma once

#include "eposp/core/event_loop.hpp"
#include "eposp/service/link.hpp"

#include <cstdint>
#include <memory>
#include <string_view>

namespace eposp::drives::escon2 {
class Escon2Drive;
}

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

/// One service interface of a device: the RS-232 or the USB port of the EPOS P, the USB port of
/// an ESCON2. The bytes of its link are framed by the protocol, each request is executed on the
/// device (its own objects, or through the EPOS P's gateway a node of its CAN ports) and
/// answered with the device's codes (docs/service-interface.md). A frame that stalls longer
/// than the frame timeout (the EPOS P's 0x5005; 500 ms on the ESCON2) is dropped and the port
/// waits for the next one; a host that hangs up ends what it started, and the port serves the
/// next host.
///
/// The port and the device must outlive nothing of each other: destroy the port first.
class ServicePort {
public:
    /// On USB, how many requests may wait while one is executed; more are dropped.
    static constexpr std::size_t kMaxQueuedRequests = 16;

    ServicePort(EposP& device, std::unique_ptr<service::Link> link, ServiceProtocol protocol);
    /// The USB port of a simulated ESCON2 on `loop` (ESCON2 FW spec 5.1): its objects, with the
    /// abort codes of table 111; it has no CAN, so it serves the object commands of NodeId 0
    /// only and answers every other command "command unknown" (0x05040001).
    ServicePort(core::EventLoop& loop, drives::escon2::Escon2Drive& drive,
                std::unique_ptr<service::Link> link);
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
