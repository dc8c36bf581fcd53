#include "eposp/canopen/lss_master.hpp"

#include <fmt/format.h>

namespace eposp::canopen {

namespace {

can::Frame request(LssCommand cs, std::initializer_list<std::uint8_t> bytes = {}) {
    return lss_frame(kLssMasterCobId, cs, bytes);
}

can::Frame request_u32(LssCommand cs, std::uint32_t value) {
    return lss_frame_u32(kLssMasterCobId, cs, value);
}

/// The meaning of a non-zero error code, which depends on the service (7.4.2.3-7.4.2.6).
std::string error_meaning(LssCommand service, std::uint8_t code, std::uint8_t specific) {
    if (code == kLssImplementationSpecificError) {
        return fmt::format("manufacturer-specific error {}", specific);
    }
    if (service == LssCommand::ConfigureNodeId && code == kLssNodeIdOutOfRange) {
        return "node-ID out of range";
    }
    if (service == LssCommand::ConfigureBitTiming && code == kLssBitTimingNotSupported) {
        return "bit timing not supported";
    }
    if (service == LssCommand::StoreConfiguration && code == kLssStoreNotSupported) {
        return "store configuration not supported";
    }
    if (service == LssCommand::StoreConfiguration && code == kLssStorageAccessError) {
        return "storage media access error";
    }
    return "reserved error";
}

} // namespace

std::string describe(const LssError& error) {
    switch (error.kind) {
    case LssErrorKind::NoAnswer:
        return fmt::format("no LSS slave answered {}", to_string(error.service));
    case LssErrorKind::NotSent:
        return fmt::format("the CAN port did not take the LSS request {}",
                           to_string(error.service));
    case LssErrorKind::Refused:
        return fmt::format("LSS slave refused {}: {} (error code {})", to_string(error.service),
                           error_meaning(error.service, error.code, error.specific), error.code);
    }
    return "unknown LSS error";
}

LssMaster::LssMaster(core::EventLoop& loop, can::Port& port, LssMasterConfig config)
    : loop_(loop), port_(port), config_(config) {}

template <typename T, typename Convert>
void LssMaster::ask(LssCommand service, std::vector<can::Frame> frames, LssCommand answer,
                    Callback<T> done, Convert convert) {
    submit({std::move(frames),
            answer,
            false,
            {},
            [service, done = std::move(done), convert](const Outcome& outcome) {
                if (!done) {
                    return;
                }
                if (!outcome.sent) {
                    done(LssError{LssErrorKind::NotSent, service});
                } else if (!outcome.answer) {
                    done(LssError{LssErrorKind::NoAnswer, service});
                } else {
                    done(convert(*outcome.answer));
                }
            }});
}

void LssMaster::on_frame(const can::Frame& frame) {
    const std::optional<LssCommand> cs = lss_command(frame, kLssSlaveCobId);
    if (!cs || !active_ || active_->answer != cs) {
        return;
    }
    if (!active_->collect) {
        finish({true, frame});
    } else if (!collected_) {
        collected_ = frame;
    }
}

void LssMaster::switch_state_global(LssState state, Callback<void> done) {
    unconfirmed({request(LssCommand::SwitchStateGlobal, {static_cast<std::uint8_t>(state)})},
                core::Duration::zero(), std::move(done));
}

void LssMaster::activate_bit_timing(std::uint16_t switch_delay_ms, std::function<void()> switch_now,
                                    Callback<void> done) {
    const core::Duration switch_delay = std::chrono::milliseconds(switch_delay_ms);
    const auto low = static_cast<std::uint8_t>(switch_delay_ms);
    const auto high = static_cast<std::uint8_t>(switch_delay_ms >> 8);
    unconfirmed({request(LssCommand::ActivateBitTiming, {low, high})}, switch_delay,
                [this, switch_delay, switch_now = std::move(switch_now),
                 done = std::move(done)](const LssResult<void>& sent) {
                    if (!sent) {
                        if (done) {
                            done(sent);
                        }
                        return;
                    }
                    if (switch_now) {
                        switch_now();
                    }
                    // The second delay goes first in the queue: nothing is sent before its end.
                    queue_.push_front(
                        {{}, std::nullopt, false, switch_delay, [done](const Outcome&) {
                             if (done) {
                                 done({});
                             }
                         }});
                });
}

void LssMaster::switch_state_selective(const LssAddress& address, Callback<void> done) {
    ask(LssCommand::SwitchStateSelectiveVendorId,
        {request_u32(LssCommand::SwitchStateSelectiveVendorId, address.vendor_id),
         request_u32(LssCommand::SwitchStateSelectiveProductCode, address.product_code),
         request_u32(LssCommand::SwitchStateSelectiveRevisionNumber, address.revision_number),
         request_u32(LssCommand::SwitchStateSelectiveSerialNumber, address.serial_number)},
        LssCommand::SwitchStateSelectiveResponse, std::move(done),
        [](const can::Frame&) { return LssResult<void>{}; });
}

void LssMaster::configure_node_id(NodeId id, Callback<void> done) {
    configure(LssCommand::ConfigureNodeId, {id}, std::move(done));
}

void LssMaster::configure_bit_timing(std::uint8_t table_selector, std::uint8_t table_index,
                                     Callback<void> done) {
    configure(LssCommand::ConfigureBitTiming, {table_selector, table_index}, std::move(done));
}

void LssMaster::store_configuration(Callback<void> done) {
    configure(LssCommand::StoreConfiguration, {}, std::move(done));
}

void LssMaster::inquire_identity(LssPart part, Callback<std::uint32_t> done) {
    const auto cs = static_cast<LssCommand>(static_cast<std::uint8_t>(LssCommand::InquireVendorId) +
                                            static_cast<std::uint8_t>(part));
    ask(cs, {request(cs)}, cs, std::move(done),
        [](const can::Frame& answer) { return LssResult<std::uint32_t>(lss_u32(answer)); });
}

void LssMaster::inquire_node_id(Callback<NodeId> done) {
    const LssCommand cs = LssCommand::InquireNodeId;
    ask(cs, {request(cs)}, cs, std::move(done),
        [](const can::Frame& answer) { return LssResult<NodeId>(answer.data[1]); });
}

void LssMaster::identify_remote_slaves(const LssAddressRange& range, Callback<bool> done) {
    identification({request_u32(LssCommand::IdentifyRemoteSlaveVendorId, range.vendor_id),
                    request_u32(LssCommand::IdentifyRemoteSlaveProductCode, range.product_code),
                    request_u32(LssCommand::IdentifyRemoteSlaveRevisionLow, range.revision_low),
                    request_u32(LssCommand::IdentifyRemoteSlaveRevisionHigh, range.revision_high),
                    request_u32(LssCommand::IdentifyRemoteSlaveSerialLow, range.serial_low),
                    request_u32(LssCommand::IdentifyRemoteSlaveSerialHigh, range.serial_high)},
                   LssCommand::IdentifySlave, std::move(done));
}

void LssMaster::identify_non_configured_slaves(Callback<bool> done) {
    identification({request(LssCommand::IdentifyNonConfiguredRemoteSlave)},
                   LssCommand::IdentifyNonConfiguredSlave, std::move(done));
}

void LssMaster::fastscan(const FastscanRequest& fastscan_request, Callback<bool> done) {
    identification({lss_fastscan_frame(fastscan_request)}, LssCommand::IdentifySlave,
                   std::move(done));
}

// The configuration services answer with their own command specifier, an error code and a
// specific error (7.4.2.3-7.4.2.6).
void LssMaster::configure(LssCommand cs, std::initializer_list<std::uint8_t> bytes,
                          Callback<void> done) {
    ask(cs, {request(cs, bytes)}, cs, std::move(done), [cs](const can::Frame& answer) {
        if (answer.data[1] != kLssSuccess) {
            return LssResult<void>(
                LssError{LssErrorKind::Refused, cs, answer.data[1], answer.data[2]});
        }
        return LssResult<void>{};
    });
}

void LssMaster::unconfirmed(std::vector<can::Frame> frames, core::Duration hold,
                            Callback<void> done) {
    const auto cs = static_cast<LssCommand>(frames[0].data[0]);
    submit({std::move(frames), std::nullopt, false, hold,
            [cs, done = std::move(done)](const Outcome& outcome) {
                if (!done) {
                    return;
                }
                if (!outcome.sent) {
                    done(LssError{LssErrorKind::NotSent, cs});
                } else {
                    done({});
                }
            }});
}

void LssMaster::identification(std::vector<can::Frame> frames, LssCommand answer,
                               Callback<bool> done) {
    const auto cs = static_cast<LssCommand>(frames[0].data[0]);
    submit(
        {std::move(frames), answer, true, {}, [cs, done = std::move(done)](const Outcome& outcome) {
             if (!done) {
                 return;
             }
             if (!outcome.sent) {
                 done(LssError{LssErrorKind::NotSent, cs});
             } else {
                 done(outcome.answer.has_value());
             }
         }});
}

void LssMaster::submit(Request request) {
    queue_.push_back(std::move(request));
    // Deferred, so that a callback never runs inside the call that made the request.
    if (!active_ && !start_.pending()) {
        start_ = core::ScopedTimer(loop_, loop_.post([this] { start_next(); }));
    }
}

void LssMaster::start_next() {
    if (active_ || queue_.empty()) {
        return;
    }
    active_ = std::move(queue_.front());
    queue_.pop_front();
    bool sent = true;
    for (const can::Frame& frame : active_->frames) {
        sent = sent && port_.send(frame) == can::SendStatus::Queued;
    }
    if (!sent) {
        finish({false, std::nullopt});
        return;
    }
    const core::Duration wait = active_->answer ? config_.timeout : active_->hold;
    timer_ = core::ScopedTimer(loop_, loop_.after(wait, [this] { finish({true, collected_}); }));
}

void LssMaster::finish(Outcome outcome) {
    timer_.cancel();
    Request finished = std::move(*active_);
    active_.reset();
    collected_.reset();
    if (finished.complete) {
        finished.complete(outcome);
    }
    start_next();
}

} // namespace eposp::canopen
