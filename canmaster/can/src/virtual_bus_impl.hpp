#pragma once

#include "eposp/can/arbitration.hpp"
#include "eposp/can/error_counters.hpp"
#include "eposp/can/frame_timing.hpp"
#include "eposp/can/virtual_bus.hpp"
#include "frame_faults.hpp"

#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

// Internal: the state behind VirtualBus and VirtualPort, shared by their two sources.
namespace eposp::can {

/// The bus's indexes of its controllers keep one bit per slot of its ports in 64-bit words.
inline constexpr std::size_t kSlotsPerWord = 64;

/// The controller behind a VirtualPort: queues, error counters, bus-off recovery.
class VirtualPort::Impl {
public:
    Impl(VirtualPort& owner, std::uint64_t connection, std::size_t tx_capacity)
        : port(owner), sequence(connection), tx_queue_capacity(tx_capacity) {}

    /// What the controller wants to send next: the babbled frame or the head of its queue.
    const Frame* next_frame() const {
        if (babbled) {
            return &*babbled;
        }
        return tx_queue.empty() ? nullptr : &tx_queue.front();
    }
    /// A frame taken from the wire: delivered now, or queued while paused or behind others.
    /// Inline: a frame goes straight to the handler, the common case, for every receiver.
    void receive(const Frame& frame, std::size_t capacity) {
        if (!paused && rx_queue.empty()) {
            ++counts.rx_frames;
            port.deliver(frame);
            return;
        }
        queue_received(frame, capacity);
    }
    void queue_received(const Frame& frame, std::size_t capacity);
    void report_overflow(Overflow overflow, const Frame& lost) const;
    void notify(ErrorState state) const { port.notify_error_state(state); }

    /// Whether the bus must hand it every frame, whatever its filter: a reception moves its
    /// receive error counter, or the frame joins its receive queue.
    bool attentive() const { return counters.receive() != 0 || paused || !rx_queue.empty(); }

    VirtualPort& port;
    const std::uint64_t sequence;   ///< connection order
    std::size_t slot = 0;           ///< its place in VirtualBus::Impl::ports
    bool attentive_indexed = false; ///< attentive() as VirtualBus::Impl's index has it
    const std::size_t tx_queue_capacity;
    std::deque<Frame> tx_queue;
    std::deque<Frame> rx_queue;
    bool paused = false;
    std::optional<Frame> babbled;
    /// arbitration_field(*next_frame()) while there is one: set as that frame changes
    /// (VirtualBus::Impl::refresh_queued()), so that arbitration compares numbers.
    std::uint32_t offered_field = 0;
    ErrorCounters counters;
    /// Frame and overflow counts; counters and state are read live. rx_frames holds the frames
    /// handed to it; those the bus did not hand it (its filter rejects them and nothing else
    /// needed the visit) are VirtualBus::Impl::unvisited_receptions().
    PortStatistics counts;
    std::uint64_t rx_base = 0; ///< see unvisited_receptions()
    core::TimePoint suspended_until{};
    OverflowHandler overflow_handler;

    // Bus-off recovery (ISO 11898-1:2015, 12.1.4): occurrences of 11 recessive bits seen.
    bool recovering = false;
    core::TimePoint counting_from{};
    std::uint64_t recessive_runs = 0;
    core::ScopedTimer recovery_timer;
};

/// How a transmission ends.
enum class Outcome {
    Delivered,       ///< received by every other controller
    Dropped,         ///< lost by fault injection
    Corrupted,       ///< bit error at the end of the CRC sequence, error frame
    NotAcknowledged, ///< nobody could acknowledge it: ACK error, error frame
};

/// The instants of one transmission, in bit times from its start of frame.
struct Timeline {
    std::size_t concluded = 0;             ///< end of EOF, or end of the error delimiter
    std::size_t bus_free = 0;              ///< end of intermission
    std::size_t recessive_from = 0;        ///< start of the recessive bits that follow
    std::optional<std::size_t> error_flag; ///< start of the error flag, if any
};

/// Plain data, copied as such once per frame (the sender's name, should it leave during its
/// frame, is kept by the bus: VirtualBus::Impl::departed_sender_name).
struct Transmission {
    VirtualPort::Impl* sender; ///< null once that port is gone
    Frame frame;
    bool from_queue; ///< false for a babbled frame, which stays
    Outcome outcome;
    FrameLength length;
    Timeline timeline;
    core::TimePoint start;
    std::uint64_t receivers_before; ///< ports connected later do not receive it
    bool concluded = false;         ///< past its end of frame (or error delimiter)
};
static_assert(std::is_trivially_copyable_v<Transmission>);

class VirtualBus::Impl {
public:
    Impl(core::EventLoop& event_loop, const BusConfig& bus_config);

    void attach(VirtualPort& port);
    void detach(VirtualPort& port);
    void request_arbitration();
    /// Precondition: some observer (callers make the event only then).
    void notify_observers(WireEvent event);

    /// Applies `change` to the counters of a port that takes part in traffic; the caller then
    /// settles the state change with settle_state() once no callback can interfere.
    template <typename Change>
    ErrorState change_counters(VirtualPort::Impl& port, Change change) {
        const ErrorState before = port.counters.state();
        if (before != ErrorState::BusOff) {
            change(port.counters);
        }
        return before;
    }
    void settle_state(VirtualPort::Impl& port, ErrorState before) {
        if (port.counters.state() != before) { // rare: inline the test, not the change
            change_state(port, before);
        }
    }
    void start_recovery(VirtualPort::Impl& port);

    core::EventLoop& loop;
    const BusConfig& config;
    core::Duration bit; ///< changes with VirtualBus::set_bitrate()
    const core::TimePoint created;

    std::vector<VirtualPort*> ports; ///< connection order; null where a port left
    bool has_vacancies = false;
    /// The connected ports recovering from bus-off: a start of frame visits the ports for
    /// their count only when there are any.
    std::size_t recovering_ports = 0;
    std::uint64_t next_sequence = 0;

    // Which controllers a frame concerns: every controller receives every frame (ISO 11898-1),
    // but one whose acceptance filter rejects it and whose receive error counter is 0 has
    // nothing to do; the bus visits the others only. One bit per slot of `ports`.
    void index_filter(VirtualPort::Impl& port);
    void refresh_attention(VirtualPort::Impl& port);
    /// After the frame it offers (its transmit queue's head or its babbled frame) may have
    /// changed: whether it takes part in arbitration, and with which arbitration field.
    /// Inline: every frame carried and every frame queued on an empty queue asks.
    void refresh_queued(VirtualPort::Impl& port) {
        const std::uint64_t mask = std::uint64_t{1} << (port.slot % kSlotsPerWord);
        std::uint64_t& word = queued[port.slot / kSlotsPerWord];
        const Frame* offered = port.next_frame();
        if (offered == nullptr) {
            word &= ~mask;
            return;
        }
        word |= mask;
        port.offered_field = arbitration_field(*offered);
    }

    // The receptions of the controllers not visited: a frame counts for each controller that
    // was not bus-off when its turn came. `delivered` frames have been handed out; while
    // `delivering` one more is, and the controllers below slot `visited_up_to` had their turn.
    std::uint64_t unvisited_receptions(const VirtualPort::Impl& port) const;
    std::uint64_t delivered = 0;
    bool delivering = false;
    std::size_t visited_up_to = 0;

    std::map<ObserverId, Observer> observers; ///< empty functions are removed ones
    ObserverId next_observer = 1;
    bool notifying = false;

    FrameFaults faults;
    BusStatistics stats;

    std::optional<Transmission> current;
    /// The name of the current transmission's sender once it has disconnected during its frame.
    std::string departed_sender_name;
    std::string_view sender_name(const Transmission& transmission) const {
        return transmission.sender != nullptr ? transmission.sender->port.name()
                                              : std::string_view(departed_sender_name);
    }
    core::TimePoint recessive_since;
    /// The deferred arbitration and the two instants of each transmission (its end of frame,
    /// then its end of intermission): alarms, not a new timer per frame. An instant that the
    /// loop would run next anyway runs in the event before it (carry_on()).
    core::Alarm arbitration;
    core::ScopedTimer suspension_end;
    core::Alarm transmission_step;

private:
    void arbitrate();
    void start(VirtualPort::Impl& sender, const Frame& frame);
    /// A fault that shortens the frame shortens `frame` itself, which then goes on the wire.
    Outcome outcome_of(const VirtualPort::Impl& sender, Frame& frame);
    bool dominant_error_flag(const VirtualPort::Impl& sender, Outcome outcome) const;
    /// Its instant after the one that has run: its end of frame or its end of intermission.
    core::TimePoint next_instant() const;
    /// `advanced`: the loop has just moved to this instant (EventLoop::advance_to()), so nothing
    /// else is due now and a call posted now would be next in line without asking.
    void step(bool advanced);
    /// After an event of the bus: the next instant of the transmission, if one is under way.
    void carry_on();
    void conclude();
    void conclude_with_error(Transmission& transmission);
    /// `next_in_line`: EventLoop::next_in_line() as it is at the end of intermission; finish()
    /// runs no callback before it arbitrates, so the answer holds there.
    void finish(bool next_in_line);
    void transmitted(Transmission& transmission);
    /// Visits the receivers of `transmission`: only those `concerning` concerns, or all.
    template <typename Visit>
    void for_each_receiver(const Transmission& transmission, const Frame* concerning, Visit visit);
    void change_state(VirtualPort::Impl& port, ErrorState before);
    /// The runs of 11 recessive bits from `stretch_start` (or later, when the controller began
    /// counting) to a start of frame.
    void count_recessive_runs(VirtualPort::Impl& controller, core::TimePoint stretch_start,
                              core::TimePoint start_of_frame) const;
    void schedule_recovery(VirtualPort::Impl& port);
    void compact_ports();
    /// Gives every port its slot and indexes all of them again.
    void reindex();
    /// Whether the frame being handed out is already counted for `port`, or not for it.
    bool settled(const VirtualPort::Impl& port) const;
    std::size_t words = 0;               ///< 64 slots a word
    std::vector<std::uint64_t> by_id;    ///< per 11-bit identifier: whose filter accepts it
    std::vector<std::uint64_t> attended; ///< whose VirtualPort::Impl::attentive() holds
    std::vector<std::uint64_t> queued;   ///< who has a frame to send (next_frame())
    core::TimePoint at_bit(core::TimePoint start, std::size_t bits) const;
};

} // namespace eposp::can
