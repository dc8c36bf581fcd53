#pragma once

#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/manager/boot_error.hpp"
#include "eposp/manager/network_list.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

namespace eposp::manager {

/// How one slave's boot-up ended, for the boot report and the error history.
struct SlaveBootResult {
    canopen::NodeId node = 0;
    std::optional<BootError> error; ///< none: booted
    std::uint32_t device_type = 0;  ///< what the slave's 0x1000 held (0 before it was read)
    canopen::LssAddress identity;   ///< the parts of its 0x1018 that were read
    core::TimePoint started{};
    core::TimePoint finished{};
};

/// The boot-up of one slave (CiA 302-2 "boot slave"; EPOS P firmware specification 8.1,
/// figure 4), by SDO: its device type 0x1000 against 0x1F84, vendor, product code, revision and
/// serial number 0x1018 against 0x1F85 - 0x1F88, its configuration date and time 0x1020
/// against 0x1F26 / 0x1F27 (each only where the expected value is not 0, date and time only
/// together), then its configuration written in order, then error control: with a consumer
/// heartbeat time, its heartbeat must come within that time. The first check that fails ends
/// the boot with its error of table 1; a request without answer ends it with NoAnswer.
///
/// The owner tells it of the slave's heartbeats (heartbeat_received) and boot-up messages
/// (node_restarted); it completes by callback, never from inside start(). Destroying it cancels
/// its SDO request.
class SlaveBoot {
public:
    using Done = std::function<void(const SlaveBootResult& result)>;

    SlaveBoot(core::EventLoop& loop, canopen::SdoClient& sdo, SlaveEntry slave, Done done);
    ~SlaveBoot();
    SlaveBoot(const SlaveBoot&) = delete;
    SlaveBoot& operator=(const SlaveBoot&) = delete;

    /// `heartbeat_seen`: the manager's heartbeat consumer has heard a heartbeat of the slave
    /// (not only its boot-up message).
    void start(bool heartbeat_seen);
    void heartbeat_received();
    /// The slave sent a boot-up message: it reset (or only now came up), so whatever the boot
    /// asked or wrote so far is void and the boot starts over. It does so once the request in
    /// flight is answered or has timed out: a new request sent now could take the old one's
    /// late answer for its own.
    void node_restarted();
    bool finished() const { return finished_; }

private:
    enum class Step : std::uint8_t {
        DeviceType,
        Identity,
        ConfigurationDate,
        ConfigurationTime,
        Configure,
        ErrorControl
    };

    void begin();
    void next();
    /// Where a request's answer lands: false when the boot is over or starts over instead.
    bool goes_on();
    void read(std::uint16_t index, std::uint8_t sub_index,
              std::function<void(std::uint32_t value)> check, BootError on_refusal);
    void check_identity_part(std::size_t part);
    void configure(std::size_t write);
    void wait_for_heartbeat();
    void finish(std::optional<BootError> error);

    core::EventLoop& loop_;
    canopen::SdoClient& sdo_;
    SlaveEntry slave_;
    Done done_;
    SlaveBootResult result_;
    Step step_ = Step::DeviceType;
    bool heartbeat_seen_ = false;
    bool finished_ = false;
    bool restart_pending_ = false;
    canopen::SdoRequestId request_;
    core::ScopedTimer heartbeat_timer_;
};

} // namespace eposp::manager
