#include "eposp/canopen/lss_fastscan.hpp"

#include <fmt/format.h>
#include <stdexcept>
#include <utility>

namespace eposp::canopen {

namespace {

constexpr std::uint8_t kHighestBit = 31;

LssPart next_part(LssPart part) {
    return part == LssPart::SerialNumber
               ? LssPart::VendorId
               : static_cast<LssPart>(static_cast<std::uint8_t>(part) + 1);
}

} // namespace

LssFastscan::LssFastscan(LssMaster& master, LssFastscanConfig config)
    : master_(master), config_(config) {}

template <typename T>
LssMaster::Callback<T> LssFastscan::guarded(std::function<void(const LssResult<T>&)> fn) {
    return [alive = std::weak_ptr<const bool>(alive_),
            fn = std::move(fn)](const LssResult<T>& result) {
        if (alive.lock()) {
            fn(result);
        }
    };
}

void LssFastscan::scan(NodeIdAllocator allocate, Done done) {
    start(std::move(done));
    allocate_ = std::move(allocate);
    // Only the slave being given its node-ID may be in configuration.
    all_to_waiting([this] { next_round(); });
}

void LssFastscan::assign(std::vector<LssAssignment> targets, Done done) {
    start(std::move(done));
    allocate_ = nullptr;
    targets_ = std::move(targets);
    all_to_waiting([this] { assign_next(); });
}

void LssFastscan::start(Done done) {
    if (running()) {
        throw std::logic_error("LssFastscan: an assignment is already running");
    }
    running_ = true;
    done_ = std::move(done);
    report_ = {};
}

// CiA 305: BitChecked 0x80 restarts every non-configured slave at the vendor-ID, and each of
// them answers.
void LssFastscan::next_round() {
    master_.fastscan({0, kFastscanConfirm, LssPart::VendorId, LssPart::VendorId},
                     guarded<bool>([this](const LssResult<bool>& answered) {
                         if (!answered) {
                             finish(core::Error{describe(answered.error())});
                         } else if (!*answered) {
                             finish(std::nullopt);
                         } else {
                             found_ = {};
                             scan_part(LssPart::VendorId);
                         }
                     }));
}

void LssFastscan::scan_part(LssPart part) {
    if (const std::optional<std::uint32_t> value = known(part)) {
        found_.set_part(part, *value);
        confirm_part(part);
        return;
    }
    scan_bit(part, kHighestBit);
}

// The bit under test is sent as 0: silence means no slave still in the race has a 0 there.
void LssFastscan::scan_bit(LssPart part, std::uint8_t bit) {
    master_.fastscan({found_.part(part), bit, part, part},
                     guarded<bool>([this, part, bit](const LssResult<bool>& answered) {
                         if (!answered) {
                             finish(core::Error{describe(answered.error())});
                             return;
                         }
                         if (!*answered) {
                             found_.set_part(part, found_.part(part) | std::uint32_t{1} << bit);
                         }
                         if (bit == 0) {
                             confirm_part(part);
                         } else {
                             scan_bit(part, static_cast<std::uint8_t>(bit - 1));
                         }
                     }));
}

// All 32 bits checked: the slaves with this value move on to the next part; after the serial
// number (LSSNext going back to the vendor-ID) the one slave left enters configuration.
void LssFastscan::confirm_part(LssPart part) {
    master_.fastscan({found_.part(part), 0, part, next_part(part)},
                     guarded<bool>([this, part](const LssResult<bool>& answered) {
                         if (!answered) {
                             finish(core::Error{describe(answered.error())});
                         } else if (!*answered) {
                             finish(core::Error{fmt::format(
                                 "LSS fastscan: no non-configured slave has the {} 0x{:08X}",
                                 to_string(part), found_.part(part))});
                         } else if (part != LssPart::SerialNumber) {
                             scan_part(next_part(part));
                         } else {
                             configure_found(allocate_(found_));
                         }
                     }));
}

void LssFastscan::assign_next() {
    if (targets_.empty()) {
        finish(std::nullopt);
        return;
    }
    const LssAssignment target = targets_.front();
    targets_.erase(targets_.begin());
    found_ = target.address;
    master_.switch_state_selective(
        found_, guarded<void>([this, node_id = target.node_id](const LssResult<void>& switched) {
            if (!switched) {
                finish(core::Error{
                    fmt::format("{} ({})", describe(switched.error()), to_string(found_))});
            } else {
                configure_found(node_id);
            }
        }));
}

// The slave at found_ is the only one in configuration.
void LssFastscan::configure_found(NodeId id) {
    if (!is_configured_node_id(id)) {
        finish(core::Error{
            fmt::format("no valid node-ID ({}) for the LSS slave with {}", id, to_string(found_))});
        return;
    }
    const auto fail = [this](const LssError& error) {
        finish(core::Error{fmt::format("{} ({})", describe(error), to_string(found_))});
    };
    const auto back_to_waiting = [this, id] {
        all_to_waiting([this, id] {
            report_.assigned.push_back({found_, id});
            if (allocate_) {
                next_round();
            } else {
                assign_next();
            }
        });
    };
    master_.configure_node_id(
        id, guarded<void>([this, fail, back_to_waiting](const LssResult<void>& configured) {
            if (!configured) {
                fail(configured.error());
            } else if (!config_.store_configuration) {
                back_to_waiting();
            } else {
                master_.store_configuration(
                    guarded<void>([fail, back_to_waiting](const LssResult<void>& stored) {
                        if (!stored) {
                            fail(stored.error());
                        } else {
                            back_to_waiting();
                        }
                    }));
            }
        }));
}

void LssFastscan::all_to_waiting(std::function<void()> then) {
    master_.switch_state_global(LssState::Waiting,
                                guarded<void>([this, then](const LssResult<void>& sent) {
                                    if (!sent) {
                                        finish(core::Error{describe(sent.error())});
                                    } else {
                                        then();
                                    }
                                }));
}

void LssFastscan::finish(std::optional<core::Error> failure) {
    if (failure) {
        // Leave no slave behind in configuration.
        master_.switch_state_global(LssState::Waiting);
    }
    LssAssignmentReport report = std::move(report_);
    report.failure = std::move(failure);
    report_ = {};
    Done done = std::exchange(done_, nullptr);
    running_ = false;
    targets_.clear();
    if (done) {
        done(report);
    }
}

std::optional<std::uint32_t> LssFastscan::known(LssPart part) const {
    switch (part) {
    case LssPart::VendorId:
        return config_.vendor_id;
    case LssPart::ProductCode:
        return config_.product_code;
    case LssPart::RevisionNumber:
        return config_.revision_number;
    case LssPart::SerialNumber:
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace eposp::canopen
