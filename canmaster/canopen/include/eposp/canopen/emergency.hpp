#pragma once

#include <cstdint>
#include <functional>

namespace eposp::canopen {

/// What a service calls when it detects an error that the node signals by EMCY; the node that
/// composes the services wires it to its EmcyProducer, with the error register bits its device
/// table gives the code (EPOS2 FW spec table 4-11).
using EmergencyCallback = std::function<void(std::uint16_t error_code)>;
/// What a service calls when an error it raised has ended: the node sends the error reset EMCY
/// (0x0000) once no other cause holds the code (CiA 301 7.2.7.1).
using ErrorResolvedCallback = std::function<void(std::uint16_t error_code)>;

/// One error condition of a service, with a lifetime: its start is raised and its end resolved,
/// each reported once however often the cause is seen in between.
class ErrorCondition {
public:
    explicit ErrorCondition(std::uint16_t code) : code_(code) {}

    /// Whether the cause holds now; a change is reported to `raise` or `resolve` (either may be
    /// empty). Inline when nothing changes: every SYNC and every RPDO asks.
    void set(bool present, const EmergencyCallback& raise, const ErrorResolvedCallback& resolve) {
        if (present != present_) {
            change(present, raise, resolve);
        }
    }
    bool present() const { return present_; }

private:
    void change(bool present, const EmergencyCallback& raise, const ErrorResolvedCallback& resolve);

    std::uint16_t code_;
    bool present_ = false;
};

// Emergency error codes the communication services raise (CiA 301 7.2.7.1).
inline constexpr std::uint16_t kEmcyNoError = 0x0000; ///< error reset or no error
/// Life guarding or heartbeat consumer timeout (EPOS2 FW spec 4.2.16).
inline constexpr std::uint16_t kEmcyLifeGuardOrHeartbeat = 0x8130;
inline constexpr std::uint16_t kEmcySyncDataLength = 0x8240; ///< unexpected SYNC data length

} // namespace eposp::canopen
