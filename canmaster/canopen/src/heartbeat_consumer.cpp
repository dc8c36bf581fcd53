#include "eposp/canopen/heartbeat_consumer.hpp"

#include "eposp/canopen/nmt_protocol.hpp"

#include <chrono>
#include <fmt/format.h>

namespace eposp::canopen {
namespace {

// What makes two entries watch the same producer: node-ID and port code.
std::uint32_t producer_of(std::uint32_t value) {
    return value >> 16;
}

// CiA 301 7.5.2 (1016h): at most one used entry per producer.
AbortCode check_unique_producer(const ObjectDictionary& od, std::uint8_t sub_index,
                                std::span<const std::uint8_t> data) {
    const auto value = decode<std::uint32_t>(data);
    if (!ConsumerHeartbeatEntry::decode(value).used()) {
        return AbortCode::None;
    }
    for (const auto& [other_sub, other] : od.find(kConsumerHeartbeatTimeIndex)->subs) {
        if (other_sub == 0 || other_sub == sub_index || other.type != DataType::Unsigned32) {
            continue;
        }
        const auto other_value = decode<std::uint32_t>(other.value);
        if (ConsumerHeartbeatEntry::decode(other_value).used() &&
            producer_of(other_value) == producer_of(value)) {
            return AbortCode::ParameterIncompatibility;
        }
    }
    return AbortCode::None;
}

} // namespace

ConsumerHeartbeatEntry ConsumerHeartbeatEntry::decode(std::uint32_t value) {
    return {.port_code = static_cast<std::uint8_t>(value >> 24),
            .node = static_cast<NodeId>(value >> 16),
            .time_ms = static_cast<std::uint16_t>(value)};
}

bool ConsumerHeartbeatEntry::used() const {
    return time_ms != 0 && node != 0 && node <= kMaxNodeId;
}

void add_heartbeat_consumer_objects(ObjectDictionary& od, std::uint8_t entries) {
    od.add_object(kConsumerHeartbeatTimeIndex, "Consumer Heartbeat Time", ObjectCode::Array);
    for (unsigned sub = 1; sub <= entries; ++sub) {
        const auto sub_index = static_cast<std::uint8_t>(sub);
        od.add_sub(kConsumerHeartbeatTimeIndex, sub_index,
                   fmt::format("Consumer {} Heartbeat Time", sub), DataType::Unsigned32,
                   Access::ReadWrite, encode(std::uint32_t{0}))
            .persistent = true;
    }
    enforce_heartbeat_consumer_rules(od);
}

void enforce_heartbeat_consumer_rules(ObjectDictionary& od) {
    Object* consumer = od.find(kConsumerHeartbeatTimeIndex);
    if (consumer == nullptr) {
        return;
    }
    for (auto& [sub_index, sub] : consumer->subs) {
        if (sub_index != 0) {
            add_write_rule(&sub, DataType::Unsigned32,
                           [&od, index = sub_index](std::span<const std::uint8_t> data) {
                               return check_unique_producer(od, index, data);
                           });
        }
    }
}

HeartbeatConsumer::HeartbeatConsumer(core::EventLoop& loop, ObjectDictionary& od,
                                     EmergencyCallback emergency, std::uint8_t port_code)
    : loop_(loop), od_(od), emergency_(std::move(emergency)), port_code_(port_code),
      listener_(od.on_change(kConsumerHeartbeatTimeIndex,
                             [this](auto, std::uint8_t sub_index) { reload_entry(sub_index); })) {}

HeartbeatConsumer::~HeartbeatConsumer() {
    od_.remove_listener(listener_);
}

void HeartbeatConsumer::receive_keys(ReceiveKeys& keys) const {
    for (const auto& [node, monitor] : monitors_) {
        keys.push_back(error_control_can_id(node));
    }
}

void HeartbeatConsumer::on_frame(const can::Frame& frame) {
    if (state_ == NmtState::Initialising || frame.extended || frame.remote || frame.error ||
        frame.dlc != 1 || frame.id <= kErrorControlCanIdBase ||
        frame.id > error_control_can_id(kMaxNodeId)) {
        return;
    }
    const auto node = static_cast<NodeId>(frame.id - kErrorControlCanIdBase);
    const auto found = monitors_.find(node);
    const std::optional<NmtState> reported = decode_nmt_state(frame.data[0]);
    if (found == monitors_.end() || !reported) {
        return;
    }
    Monitor& monitor = found->second;
    monitor.timer =
        core::ScopedTimer(loop_, loop_.after(monitor.time, [this, node] { expire(node); }));
    monitor.lost.set(false, emergency_, resolved_);
    if (monitor.state != reported) {
        monitor.state = reported;
        for (std::size_t i = 0; i < state_listeners_.size(); ++i) {
            state_listeners_[i](node, *reported);
        }
    }
}

void HeartbeatConsumer::set_nmt_state(NmtState state) {
    const NmtState previous = state_;
    state_ = state;
    if (state == NmtState::Initialising || previous == NmtState::Initialising) {
        reload();
    }
}

std::optional<NmtState> HeartbeatConsumer::remote_state(NodeId node) const {
    const auto found = monitors_.find(node);
    return found == monitors_.end() ? std::nullopt : found->second.state;
}

void HeartbeatConsumer::on_state_change(StateListener listener) {
    state_listeners_.push_back(std::move(listener));
}

void HeartbeatConsumer::on_timeout(TimeoutListener listener) {
    timeout_listeners_.push_back(std::move(listener));
}

void HeartbeatConsumer::forget(const std::function<bool(const Monitor&)>& which) {
    for (auto it = monitors_.begin(); it != monitors_.end();) {
        if (which(it->second)) {
            it->second.lost.set(false, emergency_, resolved_);
            it = monitors_.erase(it);
        } else {
            ++it;
        }
    }
}

void HeartbeatConsumer::reload() {
    forget([](const Monitor&) { return true; });
    if (state_ == NmtState::Initialising) {
        return;
    }
    for (const auto& [sub_index, sub] : od_.find(kConsumerHeartbeatTimeIndex)->subs) {
        if (sub_index != 0) {
            reload_entry(sub_index);
        }
    }
}

void HeartbeatConsumer::reload_entry(std::uint8_t sub_index) {
    if (state_ == NmtState::Initialising || sub_index == 0) {
        return;
    }
    forget([sub_index](const Monitor& monitor) { return monitor.sub_index == sub_index; });
    const auto entry = ConsumerHeartbeatEntry::decode(
        od_.get_as<std::uint32_t>(kConsumerHeartbeatTimeIndex, sub_index));
    if (entry.used() && entry.port_code == port_code_) {
        // try_emplace: an entry stored without the write check may repeat a producer; the
        // first one wins.
        monitors_.try_emplace(entry.node,
                              Monitor{.sub_index = sub_index,
                                      .time = std::chrono::milliseconds(entry.time_ms),
                                      .state = std::nullopt,
                                      .timer = {},
                                      .lost = ErrorCondition{kEmcyLifeGuardOrHeartbeat}});
    }
}

void HeartbeatConsumer::expire(NodeId node) {
    Monitor& monitor = monitors_.at(node);
    monitor.state.reset();
    monitor.lost.set(true, emergency_, resolved_);
    for (std::size_t i = 0; i < timeout_listeners_.size(); ++i) {
        timeout_listeners_[i](node);
    }
}

} // namespace eposp::canopen
