#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/result.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <variant>

namespace eposp::device {

class EposP;
class SeverablePort;

/// An axis of the axis table: its slave is the one 0x5280 + axis sub 1 assigns (10.36).
struct AxisTarget {
    std::uint8_t axis = 0;
};
/// A node on port 1 (kInternalPort: the internal EPOS2, node 1) or 2 (kExternalPort).
struct NodeTarget {
    std::uint8_t port = 0;
    canopen::NodeId node = 0;

    friend bool operator==(const NodeTarget&, const NodeTarget&) = default;
};
using FaultTarget = std::variant<AxisTarget, NodeTarget>;

/// A PDO of a slave, named from the slave's side: its RPDO is what the EPOS P sends it
/// (controlword, target), its TPDO what it sends the EPOS P (statusword, position).
enum class PdoDirection { Rpdo, Tpdo };

/// What becomes of the frames a PDO fault takes.
enum class PdoFault {
    Drop,    ///< lost on the wire for every receiver (can::VirtualBus::drop_frames)
    Shorten, ///< one data byte short: the receiver's PDO length error 0x8210 (shorten_frames)
};

/// Faults injected into the EPOS P's simulated network from a test (docs/eposp.md, "Fault
/// injection"). Each call checks its target at once and returns the reason it refuses one (no
/// such axis or node, an unassigned axis, a slave simulated in another process); an accepted
/// fault acts at the present virtual time, after the event that injects it (a PLC task's cycle)
/// has ended, in the order the calls were made. Nothing here throws for a bad argument.
///
/// The faults that act inside a slave (heartbeat, limit switch, drive error, a PDO named by its
/// number) need an EPOS2 simulated in this process: the internal EPOS2 or a slave of kind epos2
/// from EposP::add_network(). Frame faults by COB-ID work on any frame of either bus.
class FaultInjector {
public:
    explicit FaultInjector(EposP& device) : device_(device) {}
    FaultInjector(const FaultInjector&) = delete;
    FaultInjector& operator=(const FaultInjector&) = delete;

    /// The slave falls silent as if its cable broke: no heartbeat, no PDO, no SDO answer, no
    /// EMCY, and it hears nothing. The EPOS P sees it as a lost node: once the consumer time of
    /// 0x1016 has passed without a heartbeat, 0x8130 (heartbeat error) with port and node-ID in
    /// 0x1003, the slave no longer booted, its axis lost and the motion blocks on it in
    /// ErrorStop. The drive itself goes on with what it last received. Again on a silent slave:
    /// nothing more happens.
    std::optional<core::Error> drop_heartbeat(const FaultTarget& target);
    /// The silent slave's cable is back and it starts again as at power-up (its NMT boot:
    /// boot-up message, pre-operational, defaults and stored parameters, Switch On Disabled;
    /// the motor keeps its position), so the manager
    /// boots it again (8.1) and its axis is present once booted (MC_Reset takes the blocks out
    /// of ErrorStop). On a slave that is not silent: nothing happens.
    std::optional<core::Error> restore_heartbeat(const FaultTarget& target);

    /// Presses (or releases) a limit switch of the slave whatever its position; the EPOS2 reacts
    /// as to its own switch (docs/epos2.md, "Fault injection"): 0x2071 sub 1, and 0xFF06 /
    /// 0xFF07 with Fault only when its execution mask 0x2071 sub 4 has the switch (by default
    /// it has not). Pressing a pressed switch or releasing a released one changes nothing.
    std::optional<core::Error> set_limit_switch(const FaultTarget& target,
                                                drives::epos2::LimitSwitch which, bool pressed);
    /// The slave raises `code`, an error of EPOS2 FW spec table 4-11 (e.g. 0x2310 overcurrent),
    /// as if its cause had occurred: EMCY, 0x1001, 0x1003 and its reaction (docs/epos2.md,
    /// "Fault injection"); the EPOS P records the EMCY's register in 0x1002 and the axis goes to
    /// ErrorStop with it. Another code is refused. Raised again before a fault reset: no new
    /// error event.
    std::optional<core::Error> raise_drive_error(const FaultTarget& target, std::uint16_t code);

    /// The next `frames` frames of the slave's RPDO or TPDO `number` (1..4), by the COB-ID the
    /// slave's 0x1400 / 0x1800 + number - 1 holds now, suffer `fault`. The PDO must be valid.
    std::optional<core::Error> corrupt_pdo(const FaultTarget& target, PdoDirection direction,
                                           std::uint8_t number, PdoFault fault,
                                           std::uint32_t frames);
    /// The next `frames` data frames with the 11-bit `cob_id` on port 1 or 2 suffer `fault`,
    /// whoever sends them (also a slave in another process joined to port 2). Faults already
    /// waiting take their frames first: a second call adds its frames after the first's.
    std::optional<core::Error> corrupt_frames(std::uint8_t port, std::uint32_t cob_id,
                                              PdoFault fault, std::uint32_t frames);

private:
    /// An EPOS2 simulated in this process and the cable between it and its bus.
    struct SimulatedSlave {
        drives::epos2::Epos2Drive* drive;
        SeverablePort* link;
        NodeTarget where;
    };
    /// The port and node-ID of the target.
    core::Result<NodeTarget> resolve(const FaultTarget& target) const;
    core::Result<SimulatedSlave> simulated(const FaultTarget& target) const;
    /// Runs `fault` after the event that injects it.
    void inject(std::function<void()> fault);

    EposP& device_;
};

} // namespace eposp::device
