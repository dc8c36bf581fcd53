#include "eposp/canopen/emcy_producer.hpp"

#include "eposp/canopen/cob_id.hpp"
#include "eposp/canopen/emergency.hpp"

#include <chrono>

namespace eposp::canopen {
namespace {

// CiA 301 7.5.2 (1014h): the identifier may change only while the EMCY is invalid.
AbortCode check_cob_id_emcy(const ObjectDictionary& od, std::uint32_t value) {
    if ((value & kCobIdInvalid) != 0) {
        return AbortCode::None;
    }
    if (!cob_id_acceptable(value)) {
        return AbortCode::InvalidValue;
    }
    const auto current = od.get_as<std::uint32_t>(kCobIdEmcyIndex, 0);
    const bool valid = (current & kCobIdInvalid) == 0;
    return valid && (current & kCobIdIdentifierBits) != (value & kCobIdIdentifierBits)
               ? AbortCode::InvalidValue
               : AbortCode::None;
}

// CiA 301 7.3.2.2: EMCY in pre-operational and operational only.
bool sends_emcy(NmtState state) {
    return state == NmtState::PreOperational || state == NmtState::Operational;
}

} // namespace

void add_emcy_objects(ObjectDictionary& od, NodeId node_id, bool inhibit_time) {
    od.add_variable(kCobIdEmcyIndex, "COB-ID EMCY", DataType::Unsigned32, Access::ReadWrite,
                    encode(kEmcyCanIdBase + node_id))
        .persistent = true;
    enforce_emcy_rules(od);
    if (inhibit_time) {
        od.add_variable(kInhibitTimeEmcyIndex, "Inhibit Time EMCY", DataType::Unsigned16,
                        Access::ReadWrite, encode(std::uint16_t{0}))
            .persistent = true;
    }
}

void enforce_emcy_rules(ObjectDictionary& od) {
    add_write_rule(od.find(kCobIdEmcyIndex, 0), DataType::Unsigned32,
                   [&od](std::span<const std::uint8_t> data) {
                       return check_cob_id_emcy(od, decode<std::uint32_t>(data));
                   });
}

EmcyProducer::EmcyProducer(core::EventLoop& loop, can::Port& port, ObjectDictionary& od,
                           GenericErrorBit generic_bit)
    : loop_(loop), port_(port), od_(od), history_(od, generic_bit) {}

void EmcyProducer::raise(std::uint16_t error_code, std::uint8_t register_bits,
                         ManufacturerData data) {
    if (!active_.try_emplace(error_code, register_bits).second) {
        return; // EPOS2 FW spec 4.1: once per error event
    }
    history_.record(error_code);
    emit(error_code, update_register(), data);
}

void EmcyProducer::clear(std::uint16_t error_code, ManufacturerData data) {
    if (active_.erase(error_code) == 0) {
        return;
    }
    emit(kEmcyNoError, update_register(), data);
}

void EmcyProducer::clear_all(ManufacturerData data) {
    if (active_.empty()) {
        return;
    }
    active_.clear();
    emit(kEmcyNoError, update_register(), data);
}

void EmcyProducer::set_nmt_state(NmtState state) {
    const NmtState previous = state_;
    state_ = state;
    if (!sends_emcy(state)) {
        pending_.clear();
    }
    if (state == NmtState::Initialising) {
        inhibit_timer_.cancel();
        queue_retry_timer_.cancel();
    } else if (previous == NmtState::Initialising) {
        update_register(); // a reset restored 0x1001; the errors still active stay in it
    }
    if (sends_emcy(state) && reset_unsent_) {
        reset_unsent_ = false;
        emit(kEmcyNoError, update_register(), {});
    }
}

std::uint8_t EmcyProducer::update_register() {
    std::uint8_t bits = 0;
    for (const auto& [code, error_bits] : active_) {
        bits = static_cast<std::uint8_t>(bits | error_bits);
    }
    history_.set_error_register(bits);
    return history_.error_register();
}

void EmcyProducer::emit(std::uint16_t error_code, std::uint8_t error_register,
                        const ManufacturerData& data) {
    if (!sends_emcy(state_) && error_code == kEmcyNoError) {
        reset_unsent_ = true; // sent once the node may send again
        return;
    }
    const auto cob_id = od_.get_as<std::uint32_t>(kCobIdEmcyIndex, 0);
    if (!sends_emcy(state_) || (cob_id & kCobIdInvalid) != 0 || pending_.size() >= kMaxPending) {
        return;
    }
    // CiA 301 7.2.7.3.1: error code, error register, manufacturer-specific error field.
    const std::array<std::uint8_t, 8> bytes{static_cast<std::uint8_t>(error_code),
                                            static_cast<std::uint8_t>(error_code >> 8),
                                            error_register,
                                            data[0],
                                            data[1],
                                            data[2],
                                            data[3],
                                            data[4]};
    pending_.push_back(make_frame(cob_id, bytes));
    send_pending();
}

void EmcyProducer::send_pending() {
    while (!inhibit_timer_.pending() && !queue_retry_timer_.pending() && !pending_.empty()) {
        const can::SendStatus status = port_.send(pending_.front());
        if (status == can::SendStatus::BusOff) {
            return; // kept for controller_recovered()
        }
        if (status == can::SendStatus::TxOverflow) {
            queue_retry_timer_ = core::ScopedTimer(loop_, loop_.after(kQueueRetry, [this] {
                queue_retry_timer_.cancel();
                send_pending();
            }));
            return;
        }
        pending_.pop_front();
        const bool has_inhibit = od_.find(kInhibitTimeEmcyIndex, 0) != nullptr;
        const auto inhibit_100us =
            has_inhibit ? od_.get_as<std::uint16_t>(kInhibitTimeEmcyIndex, 0) : 0;
        if (inhibit_100us != 0) {
            inhibit_timer_ = core::ScopedTimer(
                loop_, loop_.after(std::chrono::microseconds(100) * inhibit_100us, [this] {
                    inhibit_timer_.cancel();
                    send_pending();
                }));
        }
    }
}

} // namespace eposp::canopen
