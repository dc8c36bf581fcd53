#pragma once

#include <cstdint>
#include <functional>

namespace eposp::plcopen {

/// An axis of the EPOS P's axis table 0x5280 - 0x529F: 0 is the internal EPOS2.
using AxisNumber = std::uint8_t;
inline constexpr AxisNumber kAxisCount = 32;

/// Whether the axis can be driven now.
enum class AxisPresence : std::uint8_t {
    Unassigned, ///< no slave is assigned to the axis (0x5280 + n sub 1 is 255)
    Lost,       ///< its slave did not boot, or its heartbeat or its PDOs stopped
    Ready,      ///< its slave is operational and its process data flow
};

/// The outcome of an SDO transfer: abort code 0 is success, with the value read (up to 32 bits)
/// and its size in bytes.
struct SdoReply {
    std::uint32_t abort_code = 0;
    std::uint32_t value = 0;
    std::uint8_t size = 0;
};
using SdoDone = std::function<void(const SdoReply& reply)>;

/// A CANopen node the CAN_* blocks address: port 1 (the internal bus) or 2 (the CAN bus) and its
/// node-ID; port 0, node 0 is the EPOS P itself (its own object dictionary).
struct NodeAddress {
    std::uint8_t port = 0;
    std::uint8_t node = 0;
};

/// What the motion blocks need of an axis' drive (DESIGN.md, "Seams"): the cyclic process data
/// of the SYNC cycle and asynchronous SDO access. The device implements it on its CANopen
/// manager; tests implement it with a fake drive. Nothing here blocks: an SDO transfer completes
/// later by calling `done`, never from inside read() or write().
class AxisLink {
public:
    virtual ~AxisLink() = default;

    virtual AxisPresence presence(AxisNumber axis) const = 0;
    /// The statusword 0x6041 and position actual value 0x6064 of the last SYNC cycle.
    virtual std::uint16_t statusword(AxisNumber axis) const = 0;
    virtual std::int32_t actual_position(AxisNumber axis) const = 0;
    /// Counts the cycles whose process data have arrived. A statusword two samples after a
    /// controlword was set answers it: the outputs go out with one SYNC, the drive answers at the
    /// next (DESIGN.md, "One communication cycle").
    virtual std::uint32_t samples(AxisNumber axis) const = 0;
    /// The controlword 0x6040 and target position 0x607A the drive receives next.
    virtual void set_controlword(AxisNumber axis, std::uint16_t controlword) = 0;
    virtual void set_target_position(AxisNumber axis, std::int32_t position) = 0;
    /// SDO upload / download of an object of the axis' drive; `size` is 1, 2 or 4 bytes.
    virtual void read(AxisNumber axis, std::uint16_t index, std::uint8_t sub_index,
                      SdoDone done) = 0;
    virtual void write(AxisNumber axis, std::uint16_t index, std::uint8_t sub_index,
                       std::uint32_t value, std::uint8_t size, SdoDone done) = 0;

    /// The same for any node (NodeAddress); a node that cannot be reached aborts the transfer.
    virtual void read(NodeAddress node, std::uint16_t index, std::uint8_t sub_index,
                      SdoDone done) = 0;
    virtual void write(NodeAddress node, std::uint16_t index, std::uint8_t sub_index,
                       std::uint32_t value, std::uint8_t size, SdoDone done) = 0;
    /// Sends an NMT command (CiA 301 7.2.8.3.1: 1 start, 2 stop, 128 pre-operational, 129 reset
    /// node, 130 reset communication) to `node` of port 1 or 2 (node 0: every node); false when
    /// there is no such port or command.
    virtual bool send_nmt(std::uint8_t port, std::uint8_t node, std::uint8_t command) = 0;
};

} // namespace eposp::plcopen
