#include "eposp/canopen/tpdo.hpp"

#include "eposp/canopen/cob_id.hpp"

namespace eposp::canopen {
namespace {

// make_frame() for a PDO: the payload's bytes beyond its size are zero, as a frame's are, so
// the eight are copied at once (every synchronous TPDO sends one at every SYNC).
can::Frame pdo_frame(std::uint32_t cob_id, const PdoPayload& payload) {
    can::Frame frame;
    frame.id = can_id(cob_id);
    frame.extended = (cob_id & kCobIdExtended) != 0;
    frame.dlc = static_cast<std::uint8_t>(payload.size);
    frame.data = payload.data;
    return frame;
}

} // namespace

Tpdo::Tpdo(core::EventLoop& loop, can::Port& port, ObjectDictionary& od, std::size_t number,
           EmergencyCallback emergency)
    : loop_(loop), port_(port), od_(od), number_(number), emergency_(std::move(emergency)) {
    const auto reload_on_change = [this](std::uint16_t, std::uint8_t) {
        reload();
    };
    config_listeners_.push_back(
        od_.on_change(pdo_communication_index(PdoDirection::Transmit, number_), reload_on_change));
    config_listeners_.push_back(
        od_.on_change(pdo_mapping_index(PdoDirection::Transmit, number_), reload_on_change));
    reload();
}

Tpdo::~Tpdo() {
    for (const auto id : config_listeners_) {
        od_.remove_listener(id);
    }
    for (const auto id : data_listeners_) {
        od_.remove_listener(id);
    }
}

bool Tpdo::event_driven() const {
    return comm_.transmission_type >= kEventDrivenManufacturer;
}

void Tpdo::reload() {
    const bool was_running = running();
    const std::uint8_t previous_type = comm_.transmission_type;
    comm_ = read_pdo_communication(od_, PdoDirection::Transmit, number_);
    auto resolution = PdoMapping::resolve(
        od_, read_pdo_mapping(od_, PdoDirection::Transmit, number_), PdoDirection::Transmit);
    mapping_ = std::move(resolution.mapping);
    active_ = comm_.cob_id.valid() && resolution.error == AbortCode::None && !mapping_.empty();
    watch_mapped_objects();
    if (was_running && running()) {
        // While valid only the transmission type, the event timer and the RTR bit can change.
        if (comm_.transmission_type != previous_type) {
            syncs_to_go_ = 0;
            sampled_.reset();
        }
        restart_event_timer();
    }
    follow_running(was_running);
}

void Tpdo::watch_mapped_objects() {
    for (const auto id : data_listeners_) {
        od_.remove_listener(id);
    }
    data_listeners_.clear();
    if (!active_ || (comm_.transmission_type != kSyncAcyclic && !event_driven())) {
        return; // only types 0, 254 and 255 have events
    }
    for (const std::uint16_t index : mapping_.mapped_indices()) {
        data_listeners_.push_back(
            od_.on_change(index, [this](std::uint16_t changed, std::uint8_t sub_index) {
                if (mapping_.maps(changed, sub_index)) {
                    request(false);
                }
            }));
    }
}

void Tpdo::set_nmt_state(NmtState state) {
    const bool was_running = running();
    operational_ = state == NmtState::Operational;
    follow_running(was_running);
}

void Tpdo::follow_running(bool was_running) {
    if (running() && !was_running) {
        start();
    } else if (!running() && was_running) {
        stop();
    }
}

void Tpdo::start() {
    syncs_to_go_ = 0;
    sampled_.reset();
    last_payload_.reset();
    last_transmission_.reset();
    request(true);
    restart_event_timer();
}

void Tpdo::stop() {
    forced_pending_ = false;
    change_pending_ = false;
    sampled_.reset();
    inhibit_timer_.cancel();
    event_timer_.cancel();
}

void Tpdo::trigger() {
    request(true);
}

void Tpdo::request(bool forced) {
    if (!running()) {
        return;
    }
    const std::uint8_t type = comm_.transmission_type;
    if (type != kSyncAcyclic && !event_driven()) {
        return; // cyclic and RTR-only PDOs have no events
    }
    forced_pending_ = forced_pending_ || forced;
    change_pending_ = change_pending_ || !forced;
    if (event_driven()) {
        send_event_if_due();
    }
}

void Tpdo::send_event_if_due() {
    if (!forced_pending_ && !change_pending_) {
        return;
    }
    // CiA 301 7.5.2.37: the inhibit time is the minimum interval between two transmissions.
    if (event_driven() && last_transmission_ && comm_.inhibit_time.count() > 0) {
        const core::TimePoint free_at = *last_transmission_ + comm_.inhibit_time;
        if (loop_.now() < free_at) {
            if (!inhibit_timer_.pending()) {
                inhibit_timer_ =
                    core::ScopedTimer(loop_, loop_.at(free_at, [this] { send_event_if_due(); }));
            }
            return;
        }
    }
    const PdoPayload payload = mapping_.pack();
    if (!forced_pending_ && payload == last_payload_) {
        change_pending_ = false; // changed back, or a write of the same value
        return;
    }
    transmit(payload);
}

void Tpdo::on_sync(std::uint8_t counter) {
    if (!running()) {
        return;
    }
    const std::uint8_t type = comm_.transmission_type;
    if (type == kSyncAcyclic) {
        send_event_if_due();
    } else if (type <= kSyncCyclicMax) {
        on_cyclic_sync(counter);
    } else if (type == kRtrSynchronous) {
        sampled_ = mapping_.pack();
    }
}

void Tpdo::on_window_closed() {
    sampled_.reset();
    // CiA 301 7.5.2.8: a synchronous PDO still waiting for the bus is too late now.
    const std::uint8_t type = comm_.transmission_type;
    if (type <= kSyncCyclicMax || type == kRtrSynchronous) {
        port_.withdraw(
            [this](const can::Frame& frame) { return matches(comm_.cob_id.raw, frame); });
    }
}

void Tpdo::on_cyclic_sync(std::uint8_t counter) {
    const std::uint8_t every = comm_.transmission_type;
    if (syncs_to_go_ == 0) {
        // CiA 301 7.5.2.37: with a SYNC start value and a SYNC counter, the first transmission
        // is at the SYNC whose counter equals the start value.
        if (comm_.sync_start != 0 && counter != 0) {
            if (counter == comm_.sync_start) {
                syncs_to_go_ = every;
                transmit(mapping_.pack());
            }
            return;
        }
        syncs_to_go_ = every;
    }
    if (--syncs_to_go_ == 0) {
        syncs_to_go_ = every;
        transmit(mapping_.pack());
    }
}

void Tpdo::on_frame(const can::Frame& frame) {
    if (!running() || frame.error || frame.extended != comm_.cob_id.extended() ||
        frame.id != comm_.cob_id.can_id()) {
        return;
    }
    if (!frame.remote) {
        if (emergency_) {
            emergency_(kEmcyTransmitCobIdCollision);
        }
        return;
    }
    if (comm_.cob_id.rtr_allowed()) {
        on_remote_request();
    }
}

void Tpdo::on_remote_request() {
    switch (comm_.transmission_type) {
    case kRtrSynchronous:
        if (sampled_) {
            transmit(*sampled_);
        }
        break;
    case kRtrEventDriven:
        transmit(mapping_.pack());
        break;
    case kEventDrivenManufacturer:
    case kEventDrivenProfile:
        request(true);
        break;
    default:
        break; // synchronous PDOs are sent at SYNC only
    }
}

void Tpdo::transmit(const PdoPayload& payload) {
    port_.send(pdo_frame(comm_.cob_id.raw, payload));
    last_payload_ = payload;
    last_transmission_ = loop_.now();
    forced_pending_ = false;
    change_pending_ = false;
    if (event_driven()) {
        restart_event_timer();
    }
}

void Tpdo::restart_event_timer() {
    event_timer_.cancel();
    if (!running() || !event_driven() || comm_.event_timer.count() == 0) {
        return;
    }
    // CiA 301 7.5.2.37: the expiry of the event timer is an event.
    event_timer_ =
        core::ScopedTimer(loop_, loop_.after(comm_.event_timer, [this] { request(true); }));
}

} // namespace eposp::canopen
