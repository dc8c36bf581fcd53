#pragma once

#include "eposp/can/frame_timing.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/lss_slave.hpp"

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eposp::canopen::testing {

/// A maxon-like LSS address (vendor-ID 0xFB is maxon's).
inline constexpr LssAddress kAddress{0x0000'00FB, 0x2001'0000, 0x0002'0003, 0x1234'5678};

inline can::Frame master_frame(LssCommand cs, std::initializer_list<std::uint8_t> bytes = {}) {
    return lss_frame(kLssMasterCobId, cs, bytes);
}

inline can::Frame master_frame_u32(LssCommand cs, std::uint32_t value) {
    return lss_frame_u32(kLssMasterCobId, cs, value);
}

inline can::Frame slave_frame(LssCommand cs, std::initializer_list<std::uint8_t> bytes = {}) {
    return lss_frame(kLssSlaveCobId, cs, bytes);
}

/// From the start of `frame` to the end of its EOF, when its receivers take it.
inline core::Duration time_to_receive(const can::Frame& frame, std::uint32_t bitrate) {
    return can::bit_duration(bitrate) *
           static_cast<std::int64_t>(can::frame_length(frame).to_end_of_frame());
}

/// A device with an LSS slave on its own port of `bus`. It performs the reset communication
/// that the slave requests, as a node would, and records what the slave stored and switched.
class SlaveNode {
public:
    SlaveNode(can::VirtualBus& bus, const std::string& name, const LssAddress& address,
              NodeId node_id = kLssUnconfiguredNodeId, bool can_store = true)
        : port_(bus.connect(name)) {
        LssSlaveConfig config;
        config.initial = {node_id, bus.config().bitrate};
        LssSlaveHooks hooks;
        hooks.request_reset_communication = [this] {
            slave_->reset_communication();
        };
        hooks.switch_bit_rate = [this](std::uint32_t rate) {
            switched_bit_rates.push_back(rate);
        };
        if (can_store) {
            hooks.store_configuration = [this](const LssConfiguration& configuration) {
                stored = configuration;
                return LssStoreResult::Stored;
            };
        }
        slave_ = std::make_unique<LssSlave>(bus.loop(), *port_, address, config, hooks);
        port_->on_receive([this](const can::Frame& frame) { slave_->on_frame(frame); });
    }
    SlaveNode(const SlaveNode&) = delete;
    SlaveNode& operator=(const SlaveNode&) = delete;

    LssSlave& slave() { return *slave_; }

    std::optional<LssConfiguration> stored;
    std::vector<std::uint32_t> switched_bit_rates;

private:
    std::unique_ptr<can::VirtualPort> port_;
    std::unique_ptr<LssSlave> slave_;
};

} // namespace eposp::canopen::testing
