#pragma once

#include "eposp/can/port.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace eposp::can {

/// How a bus-off controller comes back (ISO 11898-1:2015, 12.1.4): in both cases it becomes
/// error-active with both counters 0 after it has seen 128 occurrences of 11 consecutive
/// recessive bits on the bus; what differs is when it starts counting them.
enum class BusOffRecovery {
    Automatic, ///< at once on entering bus-off, like controllers with automatic bus-off recovery
    OnRequest, ///< only after VirtualPort::recover(), like `ip link set canX type can restart`
};

/// A gateway's port (a bridge to SocketCAN or to socketcand) gets what the other side sent in
/// bursts: one TCP read, or everything a descheduled host missed. It buffers more than a CAN
/// controller does, so such a burst reaches the bus in full.
inline constexpr std::size_t kGatewayTxQueueCapacity = 1024;

struct BusConfig {
    std::string name = "can0";         ///< the interface name traces record
    std::uint32_t bitrate = 1'000'000; ///< bit/s, 10 kbit/s ... 1 Mbit/s, a divisor of 10^9
    std::size_t tx_queue_capacity = 64;
    std::size_t rx_queue_capacity = 64;
    BusOffRecovery bus_off_recovery = BusOffRecovery::Automatic;
};

/// Something that passed the wire: a frame that was received, or an error frame signalled
/// while a frame was being sent. Traces and statistics are built from these. An error frame
/// (error_frame.hpp has its encoding) lasts from the start of the error flag to the end of the
/// error delimiter; a frame lost by fault injection is not reported.
struct WireEvent {
    core::TimePoint start; ///< start of frame
    core::TimePoint end;   ///< end of frame: the time a receiver timestamps it
    Frame frame;           ///< `frame.error` is set for an error frame
    std::string_view sender;
};

struct BusStatistics {
    std::uint64_t frames = 0;         ///< frames that reached their receivers
    std::uint64_t error_frames = 0;   ///< error frames signalled
    std::uint64_t dropped_frames = 0; ///< frames lost by fault injection
    std::uint64_t bits = 0;           ///< bit times the bus was busy, stuff bits included
    std::uint64_t stuff_bits = 0;
    core::Duration busy{};    ///< time the bus was not idle
    core::Duration elapsed{}; ///< time since the bus was created
    /// busy / elapsed, 0..1
    double load() const;
};

struct PortStatistics {
    std::uint64_t tx_frames = 0;
    std::uint64_t rx_frames = 0;
    std::uint64_t tx_overflows = 0; ///< frames refused because the transmit queue was full
    std::uint64_t rx_overflows = 0; ///< frames lost because the receive queue was full
    unsigned transmit_error_counter = 0;
    unsigned receive_error_counter = 0;
    ErrorState state = ErrorState::Active;
};

class VirtualBus;

/// A queue that was full, and so lost a frame.
enum class Overflow { Transmit, Receive };

/// A node's controller on a VirtualBus. Destroying it detaches it from the bus.
class VirtualPort final : public Port {
public:
    using OverflowHandler = std::function<void(Overflow, const Frame& lost)>;

    ~VirtualPort() override;
    VirtualPort(const VirtualPort&) = delete;
    VirtualPort& operator=(const VirtualPort&) = delete;

    SendStatus send(const Frame& frame) override;
    std::size_t withdraw(const std::function<bool(const Frame&)>& which) override;
    ErrorState error_state() const override;
    std::string_view name() const override { return name_; }

    PortStatistics statistics() const;

    /// While paused (a reader that cannot keep up), received frames wait in the receive queue;
    /// beyond its capacity they are lost and counted as receive overflows. Resuming delivers
    /// the queued frames in order.
    void pause_receive(bool paused);

    /// Told of every frame lost to a full queue, besides the counts in statistics().
    void on_overflow(OverflowHandler handler);

    /// Starts bus-off recovery under BusOffRecovery::OnRequest; does nothing unless bus-off.
    void recover();

    // Fault injection.

    /// Sets the error counters to the first value of `state` (TEC 0, 128 or 256, REC 0), as if
    /// the errors had happened; a bus-off port then recovers as configured.
    void force_error_state(ErrorState state);
    /// A babbling idiot: the controller sends `frame` back to back until stop_babbling(),
    /// ahead of its transmit queue; lower-priority traffic starves.
    void babble(const Frame& frame);
    void stop_babbling();

    class Impl;

private:
    friend class VirtualBus;
    VirtualPort(VirtualBus& bus, std::string name, std::size_t tx_queue_capacity);
    void filter_changed() override;

    VirtualBus* bus_;
    std::string name_;
    std::unique_ptr<Impl> impl_;
};

/// An in-process CAN bus on the event loop: identifier arbitration between the ports that want
/// to send, each frame occupying the wire for its true duration at the bit rate (stuff bits
/// counted from the frame's actual bits, interframe space included), per-port queues, error
/// confinement and fault injection. Deterministic: no threads, no wall clock.
///
/// - When the bus is idle, every port with a queued frame competes, including those that queue
///   one later at the same loop instant (arbitration is a deferred event); the head of each
///   port's FIFO queue takes part and the lowest arbitration field wins (arbitration.hpp).
///   Equal fields, an error on a real bus, go to the port connected first.
/// - Receivers get a frame at the end of its EOF (WireEvent::end); the next start of frame can
///   follow the 3-bit intermission; an error-passive transmitter waits 8 more bits.
/// - A frame is acknowledged when some other connected port is not bus-off (a paused one
///   acknowledges too); otherwise it ends in an ACK error and is sent again, so a node alone on
///   the bus becomes error-passive and goes on trying, as a real controller does.
/// - Errors move the counters as ISO 11898-1 says (error_counters.hpp); a controller whose
///   state changes is told through Port::on_error_state. A bus-off controller keeps its queue,
///   refuses new frames, receives nothing and recovers as BusConfig::bus_off_recovery says.
class VirtualBus {
public:
    using Observer = std::function<void(const WireEvent&)>;
    using ObserverId = std::uint64_t;
    using FrameFilter = std::function<bool(const Frame&)>;

    VirtualBus(core::EventLoop& loop, BusConfig config = {});
    ~VirtualBus();
    VirtualBus(const VirtualBus&) = delete;
    VirtualBus& operator=(const VirtualBus&) = delete;

    /// Attaches a new controller named `name` (for statistics and traces), its transmit queue
    /// as deep as BusConfig says unless `tx_queue_capacity` is given.
    std::unique_ptr<VirtualPort> connect(std::string name,
                                         std::optional<std::size_t> tx_queue_capacity = {});

    const BusConfig& config() const { return config_; }
    /// Every controller on the bus restarts at another bit rate (a device that applies its
    /// stored bit rate at power-up); frames from then on take its bit times. A rate the bus
    /// cannot have is a programming error (std::invalid_argument), as in BusConfig.
    void set_bitrate(std::uint32_t bitrate);
    core::EventLoop& loop() const { return loop_; }
    core::Duration bit_time() const;
    BusStatistics statistics() const;

    ObserverId add_observer(Observer observer);
    void remove_observer(ObserverId id);

    // Fault injection. Each fault takes the next `count` frames that start on the wire and match
    // `filter` (every frame when it is empty); faults are tried in the order they were added.
    using FaultId = std::uint64_t;

    /// The frames occupy the wire and count as sent, but no receiver or observer gets them;
    /// BusStatistics::dropped_frames counts them.
    FaultId drop_frames(FrameFilter filter = {}, std::uint64_t count = 1);
    /// A disturbance inverts the last bit of each frame's CRC sequence: the transmitter sees a
    /// bit error, an error frame follows, the error counters move, and the controller sends the
    /// frame again.
    FaultId corrupt_frames(FrameFilter filter = {}, std::uint64_t count = 1);
    /// The frames go on the wire one data byte short (DLC - 1; a remote frame or one without
    /// data passes unchanged and counts), as from a sender with a wrong PDO mapping: every receiver
    /// gets the short frame (a CANopen RPDO then reports 0x8210, PDO length error).
    FaultId shorten_frames(FrameFilter filter = {}, std::uint64_t count = 1);
    /// Removes a fault before it has taken all its frames; false when it is already gone.
    bool cancel_fault(FaultId id);

    class Impl;

private:
    friend class VirtualPort;
    core::EventLoop& loop_;
    BusConfig config_;
    std::unique_ptr<Impl> impl_;
};

} // namespace eposp::can
