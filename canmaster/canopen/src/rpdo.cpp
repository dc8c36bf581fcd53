#include "eposp/canopen/rpdo.hpp"

#include "eposp/canopen/cob_id.hpp"

namespace eposp::canopen {

Rpdo::Rpdo(core::EventLoop& loop, ObjectDictionary& od, std::size_t number,
           EmergencyCallback emergency)
    : loop_(loop), od_(od), number_(number), emergency_(std::move(emergency)) {
    const auto reload_on_change = [this](std::uint16_t, std::uint8_t) {
        reload();
    };
    listeners_.push_back(
        od_.on_change(pdo_communication_index(PdoDirection::Receive, number_), reload_on_change));
    listeners_.push_back(
        od_.on_change(pdo_mapping_index(PdoDirection::Receive, number_), reload_on_change));
    reload();
}

Rpdo::~Rpdo() {
    for (const auto id : listeners_) {
        od_.remove_listener(id);
    }
}

void Rpdo::reload() {
    comm_ = read_pdo_communication(od_, PdoDirection::Receive, number_);
    auto resolution = PdoMapping::resolve(
        od_, read_pdo_mapping(od_, PdoDirection::Receive, number_), PdoDirection::Receive);
    mapping_ = std::move(resolution.mapping);
    active_ = comm_.cob_id.valid() && resolution.error == AbortCode::None && !mapping_.empty();
    pending_.reset();
    deadline_.cancel(); // a new event timer counts from the next RPDO
    report_frame_errors(false, false, false);
}

void Rpdo::report_frame_errors(bool too_short, bool too_long, bool deadline_missed) {
    too_short_.set(too_short, emergency_, resolved_);
    too_long_.set(too_long, emergency_, resolved_);
    deadline_missed_.set(deadline_missed, emergency_, resolved_);
}

bool Rpdo::accepts(const can::Frame& frame) const {
    return active_ && operational_ && matches(comm_.cob_id.raw, frame);
}

void Rpdo::on_frame(const can::Frame& frame) {
    if (!accepts(frame)) {
        return;
    }
    const auto payload = frame.payload();
    const bool too_short = payload.size() < mapping_.size();
    // A frame that is not processed does not meet the deadline.
    report_frame_errors(too_short, payload.size() > mapping_.size(),
                        too_short && deadline_missed_.present());
    if (too_short) {
        return;
    }
    restart_deadline();
    const auto data = payload.first(mapping_.size());
    if (synchronous()) {
        if (window_closed_) {
            return;
        }
        pending_ = Bytes(data.begin(), data.end()); // the last one before the SYNC counts
    } else {
        apply(data);
    }
}

void Rpdo::apply(std::span<const std::uint8_t> data) {
    mapping_.unpack(od_, data);
    // By index: a listener may add another.
    for (std::size_t i = 0; i < applied_.size(); ++i) {
        applied_[i]();
    }
}

void Rpdo::on_sync(std::uint8_t /*counter*/) {
    window_closed_ = false;
    if (!pending_ || !operational_) {
        return;
    }
    const Bytes data = std::move(*pending_);
    pending_.reset();
    apply(data);
}

void Rpdo::on_window_closed() {
    window_closed_ = true;
}

void Rpdo::set_nmt_state(NmtState state) {
    operational_ = state == NmtState::Operational;
    if (!operational_) {
        pending_.reset();
        deadline_.cancel();
    }
}

void Rpdo::restart_deadline() {
    if (comm_.event_timer == core::Duration::zero()) {
        return;
    }
    deadline_ = core::ScopedTimer(loop_, loop_.after(comm_.event_timer, [this] {
        deadline_missed_.set(true, emergency_, resolved_);
    }));
}

} // namespace eposp::canopen
