#include "eposp/manager/slave_boot.hpp"

#include <array>
#include <utility>

namespace eposp::manager {
namespace {

constexpr std::uint16_t kDeviceTypeIndex = 0x1000;
constexpr std::uint16_t kIdentityIndex = 0x1018;
constexpr std::uint16_t kVerifyConfigurationIndex = 0x1020; // CiA 301 7.5.2.24

// 0x1018 sub 1..4 and the error of each (table 1).
constexpr std::array<canopen::LssPart, 4> kIdentityParts{
    canopen::LssPart::VendorId, canopen::LssPart::ProductCode, canopen::LssPart::RevisionNumber,
    canopen::LssPart::SerialNumber};
constexpr std::array<BootError, 4> kIdentityErrors{BootError::VendorId, BootError::ProductCode,
                                                   BootError::RevisionNumber,
                                                   BootError::SerialNumber};

} // namespace

SlaveBoot::SlaveBoot(core::EventLoop& loop, canopen::SdoClient& sdo, SlaveEntry slave, Done done)
    : loop_(loop), sdo_(sdo), slave_(std::move(slave)), done_(std::move(done)) {}

SlaveBoot::~SlaveBoot() {
    finished_ = true; // the cancelled request's callback finds the boot over
    if (request_) {
        sdo_.cancel(request_);
    }
}

void SlaveBoot::start(bool heartbeat_seen) {
    heartbeat_seen_ = heartbeat_seen;
    // The first request completes by callback: begin() never calls back from here.
    begin();
}

void SlaveBoot::begin() {
    result_ = {};
    result_.node = slave_.node_id;
    result_.started = loop_.now();
    step_ = Step::DeviceType;
    next();
}

void SlaveBoot::node_restarted() {
    if (finished_) {
        return;
    }
    heartbeat_seen_ = false; // a reset node produces its heartbeat only once configured again
    if (request_) {
        restart_pending_ = true;
        return;
    }
    heartbeat_timer_.cancel(); // waiting for a heartbeat: no request is in flight
    begin();
}

bool SlaveBoot::goes_on() {
    request_ = {};
    if (finished_) {
        return false;
    }
    if (restart_pending_) {
        restart_pending_ = false;
        begin();
        return false;
    }
    return true;
}

void SlaveBoot::heartbeat_received() {
    heartbeat_seen_ = true;
    if (step_ == Step::ErrorControl && !finished_) {
        finish(std::nullopt);
    }
}

void SlaveBoot::read(std::uint16_t index, std::uint8_t sub_index,
                     std::function<void(std::uint32_t value)> check, BootError on_refusal) {
    request_ = sdo_.upload(slave_.node_id, index, sub_index,
                           [this, check = std::move(check), on_refusal](canopen::AbortCode code,
                                                                        canopen::Bytes value) {
                               if (!goes_on()) {
                                   return;
                               }
                               if (code == canopen::AbortCode::SdoTimeout) {
                                   finish(BootError::NoAnswer);
                               } else if (code != canopen::AbortCode::None || value.size() != 4) {
                                   finish(on_refusal);
                               } else {
                                   check(canopen::decode<std::uint32_t>(value));
                               }
                           });
}

void SlaveBoot::next() {
    switch (step_) {
    case Step::DeviceType:
        // Read even when not checked: no answer here is a missing node (CiA 302-2, error B).
        read(
            kDeviceTypeIndex, 0,
            [this](std::uint32_t value) {
                result_.device_type = value;
                if (slave_.device_type != 0 && value != slave_.device_type) {
                    finish(BootError::DeviceType);
                    return;
                }
                step_ = Step::Identity;
                check_identity_part(0);
            },
            BootError::DeviceType);
        return;
    case Step::Identity:
        return; // check_identity_part() runs this step
    case Step::ConfigurationDate:
        if (slave_.configuration_date == 0 || slave_.configuration_time == 0) {
            step_ = Step::Configure;
            configure(0);
            return;
        }
        read(
            kVerifyConfigurationIndex, 1,
            [this](std::uint32_t date) {
                if (date != slave_.configuration_date) {
                    finish(BootError::ConfigurationDateTime);
                    return;
                }
                step_ = Step::ConfigurationTime;
                next();
            },
            BootError::ConfigurationDateTime);
        return;
    case Step::ConfigurationTime:
        read(
            kVerifyConfigurationIndex, 2,
            [this](std::uint32_t time) {
                if (time != slave_.configuration_time) {
                    finish(BootError::ConfigurationDateTime);
                    return;
                }
                step_ = Step::Configure;
                configure(0);
            },
            BootError::ConfigurationDateTime);
        return;
    case Step::Configure:
        return; // configure() runs this step
    case Step::ErrorControl:
        wait_for_heartbeat();
        return;
    }
}

void SlaveBoot::check_identity_part(std::size_t part) {
    while (part < kIdentityParts.size() && slave_.identity.part(kIdentityParts[part]) == 0) {
        ++part;
    }
    if (part == kIdentityParts.size()) {
        step_ = Step::ConfigurationDate;
        next();
        return;
    }
    read(
        kIdentityIndex, static_cast<std::uint8_t>(part + 1),
        [this, part](std::uint32_t value) {
            result_.identity.set_part(kIdentityParts[part], value);
            if (value != slave_.identity.part(kIdentityParts[part])) {
                finish(kIdentityErrors[part]);
                return;
            }
            check_identity_part(part + 1);
        },
        kIdentityErrors[part]);
}

// A write the slave refuses leaves it with a configuration other than the one expected.
void SlaveBoot::configure(std::size_t write) {
    if (write == slave_.configuration.size()) {
        step_ = Step::ErrorControl;
        next();
        return;
    }
    const ConfigurationWrite& entry = slave_.configuration[write];
    request_ = sdo_.download(slave_.node_id, entry.index, entry.sub_index, entry.value,
                             [this, write](canopen::AbortCode code) {
                                 if (!goes_on()) {
                                     return;
                                 }
                                 if (code == canopen::AbortCode::SdoTimeout) {
                                     finish(BootError::NoAnswer);
                                 } else if (code != canopen::AbortCode::None) {
                                     finish(BootError::ConfigurationDateTime);
                                 } else {
                                     configure(write + 1);
                                 }
                             });
}

// CiA 302-2: error control starts after the configuration; a slave whose heartbeat the
// consumer has heard is booted at once, another gets its consumer time to send one.
void SlaveBoot::wait_for_heartbeat() {
    if (slave_.heartbeat == core::Duration::zero() || heartbeat_seen_) {
        finish(std::nullopt);
        return;
    }
    heartbeat_timer_ = core::ScopedTimer(loop_, loop_.after(slave_.heartbeat, [this] {
        if (!finished_) {
            finish(BootError::ErrorControl);
        }
    }));
}

void SlaveBoot::finish(std::optional<BootError> error) {
    finished_ = true;
    heartbeat_timer_.cancel();
    result_.error = error;
    result_.finished = loop_.now();
    done_(result_);
}

} // namespace eposp::manager
