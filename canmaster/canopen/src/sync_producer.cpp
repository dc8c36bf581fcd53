#include "eposp/canopen/sync_producer.hpp"

#include "eposp/canopen/cob_id.hpp"
#include "eposp/canopen/sync_objects.hpp"

#include <chrono>
#include <vector>

namespace eposp::canopen {
namespace {

// CiA 301 7.3.2.2: SYNC in pre-operational and operational only.
bool sends_sync(NmtState state) {
    return state == NmtState::PreOperational || state == NmtState::Operational;
}

} // namespace

SyncProducer::SyncProducer(core::EventLoop& loop, can::Port& port, ObjectDictionary& od)
    : loop_(loop), port_(port), od_(od) {
    for (const std::uint16_t index :
         {kCobIdSyncIndex, kCommunicationCyclePeriodIndex, kSyncCounterOverflowIndex}) {
        od_listeners_.push_back(od.on_change(index, [this](auto, auto) { update(); }));
    }
}

SyncProducer::~SyncProducer() {
    for (const auto id : od_listeners_) {
        od_.remove_listener(id);
    }
}

void SyncProducer::set_nmt_state(NmtState state) {
    state_ = state;
    update();
}

void SyncProducer::on_sent(SentListener listener) {
    listeners_.push_back(std::move(listener));
}

SyncProducer::Config SyncProducer::read_config() const {
    // A device without a SYNC producer (add_sync_objects with producer = false, e.g. an EPOS2)
    // has neither 0x1006 nor 0x1019: it never produces.
    const auto optional_value = [this]<typename T>(std::uint16_t index, T absent) {
        return od_.find(index, 0) != nullptr ? od_.get_as<T>(index, 0) : absent;
    };
    Config config{.cob_id = od_.get_as<std::uint32_t>(kCobIdSyncIndex, 0),
                  .period_us = optional_value(kCommunicationCyclePeriodIndex, std::uint32_t{0}),
                  .overflow = optional_value(kSyncCounterOverflowIndex, std::uint8_t{0})};
    config.enabled =
        sends_sync(state_) && (config.cob_id & kCobIdGenerate) != 0 && config.period_us != 0;
    return config;
}

void SyncProducer::update() {
    const Config config = read_config();
    // Pre-operational <-> operational, or a write of the same values, keeps the cycle going.
    if (config == config_ && (producing() || !config.enabled)) {
        return;
    }
    config_ = config;
    timer_.cancel();
    counter_ = 1;
    if (config.enabled) {
        timer_ = core::ScopedTimer(
            loop_, loop_.every(std::chrono::microseconds(config.period_us), [this] { send(); }));
    }
}

void SyncProducer::send() {
    std::vector<std::uint8_t> data;
    if (config_.overflow != 0) {
        data.push_back(counter_);
        counter_ = counter_ >= config_.overflow ? 1 : static_cast<std::uint8_t>(counter_ + 1);
    }
    const can::Frame frame = make_frame(config_.cob_id, data);
    port_.send(frame);
    for (std::size_t i = 0; i < listeners_.size(); ++i) {
        listeners_[i](frame);
    }
}

} // namespace eposp::canopen
