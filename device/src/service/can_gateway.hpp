#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/service/commands.hpp"
#include "service_target.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>

namespace eposp::device {

/// The frame commands of one service link (maxon EPOS2 communication guide): NMT services,
/// CAN frames and LSS frames sent on one of the controller's CAN ports, a remote frame's
/// answer and LSS responses read back. LSS responses (0x7E4) are kept from each SendLSSFrame on
/// (the last kLssResponsesKept), since they may come before the host asks for them.
///
/// Every command completes by its callback exactly once, possibly at once; a wait in progress
/// when the link is abandoned, or the object dies, never completes.
class CanGateway {
public:
    using Done = std::function<void(service::Answer answer)>;
    /// How long RequestCANFrame waits for the answer to its remote frame.
    static constexpr core::Duration kRemoteFrameTimeout = std::chrono::milliseconds(100);
    static constexpr std::size_t kLssResponsesKept = 16;

    CanGateway(core::EventLoop& loop, const ServiceParts& parts);
    ~CanGateway();
    CanGateway(const CanGateway&) = delete;
    CanGateway& operator=(const CanGateway&) = delete;

    void send_nmt(const service::SendNmtService& request, Done done);
    void send_frame(const service::SendCanFrame& request, Done done);
    void request_frame(const service::RequestCanFrame& request, Done done);
    void send_lss(const service::SendLssFrame& request, Done done);
    void read_lss(const service::ReadLssFrame& request, Done done);
    /// The host went away: a wait ends without an answer.
    void abandon();

private:
    struct Wait;
    /// Waits on `port` for the first frame `match` accepts, or answers SDO timeout after
    /// `timeout`.
    void wait_for(NetworkPort& port, std::function<bool(const can::Frame&)> match,
                  core::Duration timeout, Done done);
    void end_wait();
    void keep_lss_responses(NetworkPort& port);

    core::EventLoop& loop_;
    const ServiceParts& parts_;
    std::unique_ptr<Wait> wait_;
    NetworkPort* lss_port_ = nullptr;
    std::uint64_t lss_observer_ = 0;
    std::deque<can::Frame> lss_responses_;
};

} // namespace eposp::device
