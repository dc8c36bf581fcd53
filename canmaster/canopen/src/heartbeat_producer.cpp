#include "eposp/canopen/heartbeat_producer.hpp"

#include "eposp/canopen/nmt_protocol.hpp"

#include <chrono>

namespace eposp::canopen {

void add_heartbeat_producer_object(ObjectDictionary& od) {
    od.add_variable(kProducerHeartbeatTimeIndex, "Producer Heartbeat Time", DataType::Unsigned16,
                    Access::ReadWrite, encode(std::uint16_t{0}))
        .persistent = true;
}

HeartbeatProducer::HeartbeatProducer(core::EventLoop& loop, can::Port& port, ObjectDictionary& od,
                                     NodeId node_id)
    : loop_(loop), port_(port), od_(od), node_id_(node_id),
      listener_(od.on_change(kProducerHeartbeatTimeIndex, [this](auto, auto) { restart(); })) {}

HeartbeatProducer::~HeartbeatProducer() {
    od_.remove_listener(listener_);
}

void HeartbeatProducer::set_nmt_state(NmtState state) {
    const NmtState previous = state_;
    state_ = state;
    // Only a reset and the boot-up after it (re)start the period; other transitions change
    // only the state the heartbeats carry.
    if (state == NmtState::Initialising || previous == NmtState::Initialising) {
        restart();
    }
}

void HeartbeatProducer::restart() {
    timer_.cancel();
    if (state_ == NmtState::Initialising) {
        return;
    }
    const auto period_ms = od_.get_as<std::uint16_t>(kProducerHeartbeatTimeIndex, 0);
    if (period_ms == 0) {
        return;
    }
    timer_ = core::ScopedTimer(
        loop_, loop_.every(std::chrono::milliseconds(period_ms), [this] { send(); }));
}

void HeartbeatProducer::send() {
    port_.send(can::Frame::data_frame(error_control_can_id(node_id_),
                                      {static_cast<std::uint8_t>(state_)}));
}

} // namespace eposp::canopen
