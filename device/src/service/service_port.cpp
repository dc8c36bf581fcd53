#include "eposp/device/service_port.hpp"

#include "eposp/core/event_loop.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/service/v1_device_link.hpp"
#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"
#include "service_commands.hpp"

#include <deque>
#include <optional>

namespace eposp::device {
namespace {

constexpr std::uint16_t kFrameTimeoutIndex = 0x5005; // EPOS P firmware specification 10.35

} // namespace

std::string_view to_string(ServiceProtocol protocol) {
    return protocol == ServiceProtocol::Rs232 ? "RS-232" : "USB";
}

class ServicePort::Impl {
public:
    Impl(EposP& device, std::unique_ptr<service::Link> link, ServiceProtocol protocol)
        : device_(device), loop_(device.loop()), link_(std::move(link)), protocol_(protocol),
          commands_(loop_, service_parts(device)) {
        link_->on_receive([this](std::span<const std::uint8_t> bytes) { receive(bytes); });
        link_->on_event([this](const service::LinkEvent&) { hang_up(); });
        const auto write = [this](std::span<const std::uint8_t> bytes) {
            link_->send(bytes);
        };
        if (protocol_ == ServiceProtocol::Rs232) {
            v1_.emplace(write, [this](const service::Frame& request) { execute(request); });
        } else {
            v2_.emplace([this](const service::Frame& request) { queue(request); },
                        [this](service::V2Error) { ++counters_.frame_errors; });
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
        const auto timeout = std::chrono::milliseconds(
            device_.objects().get_as<std::uint16_t>(kFrameTimeoutIndex, 0));
        frame_timer_ = core::ScopedTimer(loop_, loop_.after(timeout, [this] {
            if (v1_) {
                v1_->on_timeout();
            } else {
                v2_->on_timeout();
            }
        }));
    }

    void queue(const service::Frame& request) {
        if (pending_.size() >= kMaxQueuedRequests) {
            ++counters_.refused_busy;
            return;
        }
        pending_.push_back(request);
        if (!executing_) {
            execute_next();
        }
    }

    void execute_next() {
        if (pending_.empty()) {
            return;
        }
        service::Frame request = std::move(pending_.front());
        pending_.pop_front();
        execute(request);
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

    EposP& device_;
    core::EventLoop& loop_;
    std::unique_ptr<service::Link> link_;
    ServiceProtocol protocol_;
    ServiceCommands commands_;
    std::optional<service::V1DeviceLink> v1_;
    std::optional<service::V2Decoder> v2_;
    std::deque<service::Frame> pending_; ///< USB requests waiting for the one executed
    bool executing_ = false;
    std::uint64_t host_ = 0; ///< counts hang-ups: answers for an earlier host are dropped
    core::ScopedTimer frame_timer_;
    ServicePortCounters counters_;
};

ServicePort::ServicePort(EposP& device, std::unique_ptr<service::Link> link,
                         ServiceProtocol protocol)
    : impl_(std::make_unique<Impl>(device, std::move(link), protocol)) {}

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
