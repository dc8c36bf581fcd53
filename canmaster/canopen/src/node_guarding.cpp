#include "eposp/canopen/node_guarding.hpp"

#include "eposp/canopen/heartbeat_producer.hpp"
#include "eposp/canopen/nmt_protocol.hpp"

#include <chrono>

namespace eposp::canopen {
namespace {

constexpr std::uint8_t kToggleBit = 0x80;

} // namespace

void add_node_guarding_objects(ObjectDictionary& od) {
    od.add_variable(kGuardTimeIndex, "Guard Time", DataType::Unsigned16, Access::ReadWrite,
                    encode(std::uint16_t{0}))
        .persistent = true;
    od.add_variable(kLifeTimeFactorIndex, "Life Time Factor", DataType::Unsigned8,
                    Access::ReadWrite, encode(std::uint8_t{0}))
        .persistent = true;
}

NodeGuarding::NodeGuarding(core::EventLoop& loop, can::Port& port, ObjectDictionary& od,
                           NodeId node_id, EmergencyCallback emergency)
    : loop_(loop), port_(port), od_(od), node_id_(node_id), emergency_(std::move(emergency)) {
    // A new guard time, life time factor or heartbeat time counts from the write.
    for (const std::uint16_t index :
         {kGuardTimeIndex, kLifeTimeFactorIndex, kProducerHeartbeatTimeIndex}) {
        od_listeners_.push_back(od.on_change(index, [this](auto, auto) { rearm(); }));
    }
}

NodeGuarding::~NodeGuarding() {
    for (const auto id : od_listeners_) {
        od_.remove_listener(id);
    }
}

void NodeGuarding::receive_keys(ReceiveKeys& keys) const {
    keys.push_back(error_control_can_id(node_id_));
}

void NodeGuarding::on_frame(const can::Frame& frame) {
    if (state_ == NmtState::Initialising || !frame.remote || frame.extended || frame.error ||
        frame.id != error_control_can_id(node_id_) || heartbeat_in_use()) {
        return;
    }
    const auto reply =
        static_cast<std::uint8_t>((toggle_ ? kToggleBit : 0) | static_cast<std::uint8_t>(state_));
    port_.send(can::Frame::data_frame(error_control_can_id(node_id_), {reply}));
    toggle_ = !toggle_;
    guarded_ = true;
    if (life_guarding_event_.present()) {
        life_guarding_event_.set(false, emergency_, resolved_);
        tell(false);
    }
    rearm();
}

void NodeGuarding::set_nmt_state(NmtState state) {
    state_ = state;
    if (state == NmtState::Initialising) {
        // CiA 301 7.2.8.3.2.1: a reset starts the toggle at 0 and life guarding anew.
        toggle_ = false;
        guarded_ = false;
        life_guarding_event_.set(false, emergency_, resolved_);
        life_timer_.cancel();
    }
}

void NodeGuarding::on_life_guarding_event(LifeGuardingListener listener) {
    listeners_.push_back(std::move(listener));
}

bool NodeGuarding::heartbeat_in_use() const {
    return od_.find(kProducerHeartbeatTimeIndex, 0) != nullptr &&
           od_.get_as<std::uint16_t>(kProducerHeartbeatTimeIndex, 0) != 0;
}

core::Duration NodeGuarding::life_time() const {
    const auto guard_time = od_.get_as<std::uint16_t>(kGuardTimeIndex, 0);
    const auto factor = od_.get_as<std::uint8_t>(kLifeTimeFactorIndex, 0);
    return std::chrono::milliseconds(guard_time) * factor;
}

void NodeGuarding::rearm() {
    life_timer_.cancel();
    if (!guarded_ || life_guarding_event_.present() || state_ == NmtState::Initialising ||
        heartbeat_in_use()) {
        return;
    }
    const core::Duration life = life_time();
    if (life == core::Duration::zero()) {
        return;
    }
    life_timer_ = core::ScopedTimer(loop_, loop_.after(life, [this] { expire(); }));
}

void NodeGuarding::expire() {
    life_guarding_event_.set(true, emergency_, resolved_);
    tell(true);
}

void NodeGuarding::tell(bool occurred) {
    for (std::size_t i = 0; i < listeners_.size(); ++i) {
        listeners_[i](occurred);
    }
}

} // namespace eposp::canopen
