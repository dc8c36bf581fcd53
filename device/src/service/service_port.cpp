#include "eposp/device/service_port.hpp"

#include "eposp/core/event_loop.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/service/v1_device_link.hpp"
#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"
#include "service_commands.hpp"

#include <deque>
#include <optional>

namespace eposp::device {

std::string_view to_string(ServiceProtocol protocol) {
    return protocol == ServiceProtocol::Rs232 ? "RS-232" : "USB";
}

class ServicePort::Impl {
public:
    Impl(core::EventLoop& loop, ServiceParts parts, std::unique_ptr<service::Link> link,
         ServiceProtocol protocol)
        : loop_(loop), link_(std::move(link)), protocol_(protocol),
          commands_(loop_, std::move(parts)) {
        link_->on_receive([this](std::span<const std::uint8_t> bytes) { receive(bytes); });
        link_->on_event([this](const service::LinkEvent&) { hang_up(); });
        const auto write = [this](std::span<const std::uint8_t> bytes) {
            link_->send(bytes);
        };
        if (protocol_ == ServiceProtocol::Rs232) {
            v1_.emplace(write, [this](const service::Frame& request) { execute(request); });
        } else {
            v2_.emplace([this](const service::Frame& request) { queue({request}); },
                        [this](service::V2Error error) { frame_error(error); });
        }
    }

    ~Impl() {
        // The commands' callbacks refer to this: none may come once it goes.
        commands_.abandon();
    }

    ServiceProtocol protocol() const { return protocol_; }
    const service::Link& link() const { return *link_; }
    ServicePortCounters counters() const {
        ServicePortCounters counters = counters_;
        if (v1_) {
            counters.frame_errors += v1_->counters().crc_errors + v1_->counters().timeouts;
            counters.refused_busy += v1_->counters().refused_busy;
        }
        return counters;
    }

private:
    void receive(std::span<const std::uint8_t> bytes) {
        if (v1_) {
            v1_->receive(bytes);
        } else {
            v2_->receive(bytes);
        }
        watch_frame_time();
    }

    bool mid_frame() const { return v1_ ? v1_->mid_frame() : v2_->mid_frame(); }

    // EPOS P firmware specification 10.35: a frame may take at most 0x5005 ms; each byte
    // restarts the time.
    void watch_frame_time() {
        frame_timer_.cancel();
        if (!mid_frame()) {
            return;
        }
        const core::Duration timeout = commands_.parts().frame_timeout();
        frame_timer_ = core::ScopedTimer(loop_, loop_.after(timeout, [this] {
            if (v1_) {
                v1_->on_timeout();
            } else {
                v2_->on_timeout();
            }
        }));
    }

    // A request, or the error a dropped one is answered with (the ESCON2's CRC error).
    struct Pending {
        service::Frame request;
        std::uint32_t refusal = service::error::kNone;
    };

    void frame_error(service::V2Error error) {
        ++counters_.frame_errors;
        // ESCON2 FW spec table 111: the device answers a frame whose CRC failed, so the host
        // learns at once instead of waiting for its timeout.
        if (error == service::V2Error::CrcError && commands_.parts().dialect.answers_crc_errors) {
            queue({{}, static_cast<std::uint32_t>(canopen::AbortCode::CrcError)});
        }
    }

    void queue(Pending request) {
        if (pending_.size() >= kMaxQueuedRequests) {
            ++counters_.refused_busy;
            return;
        }
        pending_.push_back(std::move(request));
        if (!executing_) {
            execute_next();
        }
    }

    void execute_next() {
        if (pending_.empty()) {
            return;
        }
        Pending next = std::move(pending_.front());
        pending_.pop_front();
        if (next.refusal != service::error::kNone) {
            executing_ = true;
            return answer_request(next.request.opcode, service::encode_answer({next.refusal, {}}));
        }
        execute(next.request);
    }

    void execute(const service::Frame& request) {
        ++counters_.requests;
        executing_ = true;
        const std::uint64_t host = host_;
        commands_.execute(request, [this, host, opcode = request.opcode](service::Frame answer) {
            if (host != host_) {
                return; // for a host that hung up
            }
            // Answered from inside execute() or later: the link's state machine is ready for
            // it either way, so answer now.
            answer_request(opcode, answer);
        });
    }

    void answer_request(std::uint8_t opcode, const service::Frame& answer) {
        executing_ = false;
        if (v1_) {
            if (service::answered_on_v1(opcode)) {
                v1_->send_answer(answer);
                ++counters_.answers;
            } else {
                v1_->skip_answer();
            }
            watch_frame_time();
            return;
        }
        link_->send(service::encode_v2(answer));
        ++counters_.answers;
        // The next request runs after this one's callback returned.
        loop_.post([this, host = host_] {
            if (host == host_ && !executing_) {
                execute_next();
            }
        });
    }

    // The host went away: what it started ends unanswered, and the port waits for the next.
    void hang_up() {
        ++counters_.hang_ups;
        ++host_;
        commands_.abandon();
        pending_.clear();
        executing_ = false;
        frame_timer_.cancel();
        if (v1_) {
            if (v1_->awaiting_answer()) {
                v1_->skip_answer();
            } else if (v1_->mid_frame()) {
                v1_->on_timeout();
            }
        } else if (v2_->mid_frame()) {
            v2_->on_timeout();
        }
    }

    core::EventLoop& loop_;
    std::unique_ptr<service::Link> link_;
    ServiceProtocol protocol_;
    ServiceCommands commands_;
    std::optional<service::V1DeviceLink> v1_;
    std::optional<service::V2Decoder> v2_;
    std::deque<Pending> pending_; ///< USB requests waiting for the one executed
    bool executing_ = false;
    std::uint64_t host_ = 0; ///< counts hang-ups: answers for an earlier host are dropped
    core::ScopedTimer frame_timer_;
    ServicePortCounters counters_;
};

ServicePort::ServicePort(EposP& device, std::unique_ptr<service::Link> link,
                         ServiceProtocol protocol)
    : impl_(std::make_unique<Impl>(device.loop(), service_parts(device), std::move(link),
                                   protocol)) {}

ServicePort::ServicePort(core::EventLoop& loop, drives::escon2::Escon2Drive& drive,
                         std::unique_ptr<service::Link> link)
    : impl_(std::make_unique<Impl>(loop, service_parts(drive), std::move(link),
                                   ServiceProtocol::Usb)) {}

ServicePort::~ServicePort() = default;

ServiceProtocol ServicePort::protocol() const {
    return impl_->protocol();
}
const service::Link& ServicePort::link() const {
    return impl_->link();
}
ServicePortCounters ServicePort::counters() const {
    return impl_->counters();
}

} // namespace eposp::device
