#include "eposp/can/virtual_bus.hpp"

#include "eposp/can/error_frame.hpp"
#include "virtual_bus_impl.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace eposp::can {
namespace {

constexpr std::uint32_t kMinBitrate = 10'000;
constexpr std::uint32_t kMaxBitrate = 1'000'000;
constexpr std::uint64_t kNanosecondsPerSecond = 1'000'000'000;
/// ISO 11898-1:2015, 12.1.4: bus-off recovery waits for 128 runs of 11 recessive bits.
constexpr std::uint64_t kBusOffRecoveryRuns = 128;
/// The ACK slot and the ACK delimiter follow the CRC delimiter.
constexpr std::size_t kAckSlotAfterCrc = 1;
constexpr std::size_t kAckDelimiterAfterCrc = 2;
constexpr std::size_t kStandardIds = std::size_t{1} << 11;

const BusConfig& validated(const BusConfig& config) {
    if (config.bitrate < kMinBitrate || config.bitrate > kMaxBitrate ||
        kNanosecondsPerSecond % config.bitrate != 0) {
        throw std::invalid_argument("VirtualBus: the bit rate must be 10 kbit/s ... 1 Mbit/s and "
                                    "divide 10^9, so that a bit time is a whole number of ns");
    }
    return config;
}

// ISO 11898-1:2015, 10.4.4: an error frame is the error flag and the error delimiter; the
// intermission follows. The flag is the 6 bits of one node: all nodes detect a disturbance of
// the wire at the same bit, so their flags coincide.
Timeline error_timeline(std::size_t error_flag, std::size_t recessive_from) {
    const std::size_t delimiter_end = error_flag + kErrorFlagBits + kErrorDelimiterBits;
    return {.concluded = delimiter_end,
            .bus_free = delimiter_end + kIntermissionBits,
            .recessive_from = recessive_from,
            .error_flag = error_flag};
}

/// `dominant_flag`: some node that detects the error is error-active and sends an active
/// (dominant) error flag; error-passive nodes send recessive ones.
Timeline timeline_of(Outcome outcome, const FrameLength& length, bool dominant_flag) {
    const std::size_t crc_end = length.stuffed;
    switch (outcome) {
    case Outcome::Delivered:
    case Outcome::Dropped:
        // The receivers' dominant ACK is the last dominant bit.
        return {.concluded = length.to_end_of_frame(),
                .bus_free = length.total(),
                .recessive_from = crc_end + kAckDelimiterAfterCrc,
                .error_flag = std::nullopt};
    case Outcome::Corrupted:
        // 10.4.4.2: the flag starts at the bit after the error, here after the CRC sequence.
        // With only passive flags the recessive run is taken to start with the flag.
        return error_timeline(crc_end, dominant_flag ? crc_end + kErrorFlagBits : crc_end);
    case Outcome::NotAcknowledged: {
        // The transmitter sees the ACK slot recessive and flags the error at the next bit.
        const std::size_t flag = crc_end + kAckSlotAfterCrc + 1;
        return error_timeline(flag, dominant_flag ? flag + kErrorFlagBits
                                                  : crc_end - length.trailing_recessive);
    }
    }
    throw std::logic_error("unknown transmission outcome");
}

} // namespace

// --- the controller's side ----------------------------------------------------------------

void VirtualPort::Impl::queue_received(const Frame& frame, std::size_t capacity) {
    if (rx_queue.size() >= capacity) {
        ++counts.rx_overflows;
        report_overflow(Overflow::Receive, frame);
        return;
    }
    ++counts.rx_frames;
    rx_queue.push_back(frame);
}

void VirtualPort::Impl::report_overflow(Overflow overflow, const Frame& lost) const {
    if (overflow_handler) {
        overflow_handler(overflow, lost);
    }
}

// --- the bus ------------------------------------------------------------------------------

VirtualBus::Impl::Impl(core::EventLoop& event_loop, const BusConfig& bus_config)
    : loop(event_loop), config(bus_config), bit(bit_duration(bus_config.bitrate)),
      created(event_loop.now()), recessive_since(created),
      arbitration(event_loop,
                  [this] {
                      arbitrate();
                      carry_on();
                  }),
      transmission_step(event_loop, [this] {
          step(false);
          carry_on();
      }) {}

core::TimePoint VirtualBus::Impl::at_bit(core::TimePoint start, std::size_t bits) const {
    return start + bit * static_cast<std::int64_t>(bits);
}

void VirtualBus::Impl::attach(VirtualPort& port) {
    ports.push_back(&port);
    // The frame being handed out now is not for it.
    port.impl_->rx_base = delivered + (delivering ? 1 : 0);
    if (ports.size() > words * kSlotsPerWord) {
        reindex();
        return;
    }
    port.impl_->slot = ports.size() - 1;
    index_filter(*port.impl_);
    refresh_attention(*port.impl_);
    refresh_queued(*port.impl_);
}

void VirtualBus::Impl::reindex() {
    words = (ports.size() + kSlotsPerWord - 1) / kSlotsPerWord;
    by_id.assign(kStandardIds * words, 0);
    attended.assign(words, 0);
    queued.assign(words, 0);
    for (std::size_t slot = 0; slot < ports.size(); ++slot) {
        if (ports[slot] != nullptr) {
            ports[slot]->impl_->slot = slot;
            index_filter(*ports[slot]->impl_);
            refresh_attention(*ports[slot]->impl_);
            refresh_queued(*ports[slot]->impl_);
        }
    }
}

void VirtualBus::Impl::index_filter(VirtualPort::Impl& port) {
    const std::size_t word = port.slot / kSlotsPerWord;
    const std::uint64_t mask = std::uint64_t{1} << (port.slot % kSlotsPerWord);
    for (std::size_t id = 0; id < kStandardIds; ++id) {
        std::uint64_t& accepting = by_id[id * words + word];
        accepting = port.port.accepts(static_cast<std::uint32_t>(id)) ? accepting | mask
                                                                      : accepting & ~mask;
    }
}

void VirtualBus::Impl::refresh_attention(VirtualPort::Impl& port) {
    const std::uint64_t mask = std::uint64_t{1} << (port.slot % kSlotsPerWord);
    std::uint64_t& word = attended[port.slot / kSlotsPerWord];
    port.attentive_indexed = port.attentive();
    word = port.attentive_indexed ? word | mask : word & ~mask;
}

bool VirtualBus::Impl::settled(const VirtualPort::Impl& port) const {
    return delivering && (current->sender == &port || port.sequence >= current->receivers_before ||
                          port.slot < visited_up_to);
}

std::uint64_t VirtualBus::Impl::unvisited_receptions(const VirtualPort::Impl& port) const {
    if (port.counters.state() == ErrorState::BusOff) {
        return 0;
    }
    return delivered + (settled(port) ? 1 : 0) - port.rx_base;
}

void VirtualBus::Impl::detach(VirtualPort& port) {
    std::ranges::replace(ports, &port, nullptr);
    recovering_ports -= port.impl_->recovering ? 1 : 0;
    has_vacancies = true;
    if (current && current->sender == port.impl_.get()) {
        departed_sender_name = std::string(port.name());
        current->sender = nullptr;
    }
}

void VirtualBus::Impl::compact_ports() {
    if (has_vacancies) {
        std::erase(ports, nullptr);
        has_vacancies = false;
        reindex();
    }
}

void VirtualBus::Impl::notify_observers(WireEvent event) {
    // The sender's name as it is now: an observer might even disconnect the sending port.
    const std::string sender(event.sender);
    event.sender = sender;
    // Observers added by an observer see the next event; removed ones are erased afterwards.
    const ObserverId end = next_observer;
    notifying = true;
    for (const auto& [id, observer] : observers) {
        if (id >= end) {
            break;
        }
        if (observer) {
            observer(event);
        }
    }
    notifying = false;
    std::erase_if(observers, [](const auto& entry) { return !entry.second; });
}

// Frames queued at the same instant must all compete, so arbitration is a deferred event.
void VirtualBus::Impl::request_arbitration() {
    if (!current && !arbitration.armed()) {
        arbitration.arm(loop.now());
    }
}

// ISO 11898-1:2015, 10.4.2.3: the lowest arbitration field wins. Each controller offers the
// head of its FIFO queue. Equal fields (the same frame from two controllers, an error on a
// real bus) go to the controller connected first. Only those with a frame are visited, in
// connection order.
void VirtualBus::Impl::arbitrate() {
    compact_ports();
    const core::TimePoint now = loop.now();
    VirtualPort::Impl* winner = nullptr;
    std::uint32_t winning_field = 0; // the winner's arbitration field (wins_arbitration)
    std::optional<core::TimePoint> suspended_until;
    for (std::size_t word = 0; word < words; ++word) {
        for (std::uint64_t sending = queued[word]; sending != 0; sending &= sending - 1) {
            const std::size_t slot =
                word * kSlotsPerWord + static_cast<std::size_t>(std::countr_zero(sending));
            VirtualPort::Impl& controller = *ports[slot]->impl_;
            if (controller.counters.state() == ErrorState::BusOff) {
                continue;
            }
            if (controller.suspended_until > now) {
                suspended_until = std::min(suspended_until.value_or(controller.suspended_until),
                                           controller.suspended_until);
                continue;
            }
            if (winner == nullptr || controller.offered_field < winning_field) {
                winner = &controller;
                winning_field = controller.offered_field;
            }
        }
    }
    if (winner != nullptr) {
        suspension_end.cancel();
        start(*winner, *winner->next_frame());
    } else if (suspended_until) {
        suspension_end =
            core::ScopedTimer(loop, loop.at(*suspended_until, [this] { request_arbitration(); }));
    }
}

Outcome VirtualBus::Impl::outcome_of(const VirtualPort::Impl& sender, Frame& frame) {
    // ISO 11898-1:2015, 10.4.2.7: some other controller that takes part in traffic sends the
    // dominant ACK; without one the transmitter detects an ACK error.
    const bool acknowledged = std::ranges::any_of(ports, [&sender](const VirtualPort* port) {
        return port != nullptr && port->impl_.get() != &sender &&
               port->impl_->counters.state() != ErrorState::BusOff;
    });
    if (!acknowledged) {
        return Outcome::NotAcknowledged;
    }
    const std::optional<FrameFault> fault = faults.take(frame);
    if (!fault) {
        return Outcome::Delivered;
    }
    switch (*fault) {
    case FrameFault::Drop:
        return Outcome::Dropped;
    case FrameFault::Corrupt:
        return Outcome::Corrupted;
    case FrameFault::Shorten:
        if (!frame.remote && frame.dlc > 0) {
            --frame.dlc;
            frame.data[frame.dlc] = 0;
        }
        break;
    }
    return Outcome::Delivered;
}

bool VirtualBus::Impl::dominant_error_flag(const VirtualPort::Impl& sender, Outcome outcome) const {
    const auto active = [](const VirtualPort::Impl& controller) {
        return error_active(controller.counters.state());
    };
    if (outcome == Outcome::NotAcknowledged) {
        return active(sender);
    }
    return std::ranges::any_of(ports, [&active](const VirtualPort* port) {
        return port != nullptr && active(*port->impl_);
    });
}

void VirtualBus::Impl::start(VirtualPort::Impl& sender, const Frame& next) {
    Frame frame = next;
    const Outcome outcome = outcome_of(sender, frame);
    const FrameLength length = frame_length(frame);
    // Only an error frame has a flag whose kind matters.
    const bool error = outcome == Outcome::Corrupted || outcome == Outcome::NotAcknowledged;
    const Timeline timeline =
        timeline_of(outcome, length, error && dominant_error_flag(sender, outcome));
    const core::TimePoint now = loop.now();

    // A recovering controller counts the recessive stretch this frame ends and waits on the next.
    const core::TimePoint stretch_start = recessive_since;
    recessive_since = at_bit(now, timeline.recessive_from);
    if (recovering_ports > 0) {
        for (VirtualPort* port : ports) {
            if (port->impl_->recovering) {
                count_recessive_runs(*port->impl_, stretch_start, now);
                schedule_recovery(*port->impl_);
            }
        }
    }

    if (outcome == Outcome::Delivered) {
        // A controller does not receive its own frame: counted as settled for it at once.
        delivering = true;
        visited_up_to = 0;
        ++sender.rx_base;
    }
    current = Transmission{.sender = &sender,
                           .frame = frame,
                           .from_queue = !sender.babbled,
                           .outcome = outcome,
                           .length = length,
                           .timeline = timeline,
                           .start = now,
                           .receivers_before = next_sequence};
}

core::TimePoint VirtualBus::Impl::next_instant() const {
    return at_bit(current->start,
                  current->concluded ? current->timeline.bus_free : current->timeline.concluded);
}

void VirtualBus::Impl::step(bool advanced) {
    if (current->concluded) {
        finish(advanced || loop.next_in_line());
    } else {
        conclude();
    }
}

// Each instant of a transmission (its end of frame, its end of intermission with the next
// arbitration and start of frame) is an event of the loop, unless the loop would run that event
// next anyway: then no event, handler, statistics read or caller of run_until() can come
// between, and this event goes on with it.
void VirtualBus::Impl::carry_on() {
    while (current && loop.advance_to(next_instant())) {
        step(true);
    }
    if (current) {
        transmission_step.arm(next_instant());
    }
}

template <typename Visit>
void VirtualBus::Impl::for_each_receiver(const Transmission& transmission, const Frame* concerning,
                                         Visit visit) {
    // By index: a callback may connect ports (they come after `count`) or disconnect them (their
    // slot becomes null; compaction waits for the next arbitration). The index is read as it is
    // at each step: a callback may change a filter, as on a real bus before that frame's turn.
    const std::size_t count = ports.size();
    // Acceptance filters pass every 29-bit frame.
    const bool everyone = concerning == nullptr || concerning->extended;
    const std::size_t id = everyone ? 0 : concerning->id;
    // The slots of `word` that the frame concerns, as the index is now.
    const auto concerned = [this, everyone, id](std::size_t word) {
        return everyone ? ~std::uint64_t{0} : by_id[id * words + word] | attended[word];
    };
    // The sender does not receive its own frame: its slot is left out. Slots stay put until the
    // next arbitration compacts the ports, and a slot left by a port that disconnects stays empty.
    const std::size_t own = transmission.sender != nullptr ? transmission.sender->slot : count;
    const auto visit_slot = [&](std::size_t i) {
        VirtualPort* port = ports[i];
        visited_up_to = i + 1;
        if (port == nullptr || port->impl_->sequence >= transmission.receivers_before ||
            port->impl_->counters.state() == ErrorState::BusOff) {
            return;
        }
        const bool attentive = port->impl_->attentive_indexed;
        const ErrorState before = visit(*port->impl_);
        // A reception only counts the receive error counter down and empties no queue: a port
        // that was not attentive stays so (pause_receive() refreshes itself); an error counts up.
        if (ports[i] == port) {
            if (attentive || concerning == nullptr) {
                refresh_attention(*port->impl_);
            }
            settle_state(*port->impl_, before);
        }
    };
    for (std::size_t word = 0; word * kSlotsPerWord < count; ++word) {
        const std::uint64_t others = word == own / kSlotsPerWord
                                         ? ~(std::uint64_t{1} << (own % kSlotsPerWord))
                                         : ~std::uint64_t{0};
        for (std::uint64_t left = concerned(word) & others; left != 0;) {
            const std::size_t place = static_cast<std::size_t>(std::countr_zero(left));
            const std::size_t i = word * kSlotsPerWord + place;
            if (i >= count) {
                break;
            }
            // The slots after `i`, read again after the visit (no shift by 64).
            const std::uint64_t after = ~std::uint64_t{1} << place;
            visit_slot(i);
            left = concerned(word) & after & others;
        }
    }
}

void VirtualBus::Impl::conclude() {
    Transmission& transmission = *current;
    transmission.concluded = true;
    switch (transmission.outcome) {
    case Outcome::Delivered:
        ++stats.frames;
        // The event (with the sender's name, a virtual call) is made only for observers.
        if (!observers.empty()) {
            notify_observers({.start = transmission.start,
                              .end = at_bit(transmission.start, transmission.timeline.concluded),
                              .frame = transmission.frame,
                              .sender = sender_name(transmission)});
        }
        transmitted(transmission);
        for_each_receiver(
            transmission, &transmission.frame, [this, &transmission](VirtualPort::Impl& receiver) {
                const ErrorState before = change_counters(
                    receiver, [](ErrorCounters& counters) { counters.receive_success(); });
                ++receiver.rx_base; // counted in its own counts
                receiver.receive(transmission.frame, config.rx_queue_capacity);
                return before;
            });
        ++delivered;
        delivering = false;
        break;
    case Outcome::Dropped:
        ++stats.dropped_frames;
        transmitted(transmission);
        break;
    case Outcome::Corrupted:
    case Outcome::NotAcknowledged:
        conclude_with_error(transmission);
        break;
    }
}

void VirtualBus::Impl::transmitted(Transmission& transmission) {
    if (transmission.sender == nullptr) {
        return;
    }
    VirtualPort::Impl& sender = *transmission.sender;
    if (transmission.from_queue && !sender.tx_queue.empty()) {
        sender.tx_queue.pop_front();
        refresh_queued(sender);
    }
    ++sender.counts.tx_frames;
    settle_state(sender, change_counters(
                             sender, [](ErrorCounters& counters) { counters.transmit_success(); }));
}

void VirtualBus::Impl::conclude_with_error(Transmission& transmission) {
    ++stats.error_frames;
    const bool ack_error = transmission.outcome == Outcome::NotAcknowledged;
    const auto transmit_error = [ack_error](ErrorCounters& counters) {
        counters.transmit_error(ack_error);
    };

    // The error frame shows the transmitter's counters after the error.
    ErrorCounters after = transmission.sender ? transmission.sender->counters : ErrorCounters{};
    const ErrorState before = after.state();
    if (before != ErrorState::BusOff) {
        transmit_error(after);
    }
    const bool state_changed = after.state() != before;
    const bool sent_recessive = transmission.length.trailing_recessive > 0;
    if (!observers.empty()) {
        notify_observers(
            {.start = at_bit(transmission.start, *transmission.timeline.error_flag),
             .end = at_bit(transmission.start, transmission.timeline.concluded),
             .frame = ack_error ? ack_error_frame(after, state_changed)
                                : crc_sequence_bit_error_frame(sent_recessive, after, state_changed),
             .sender = sender_name(transmission)});
    }

    if (transmission.sender != nullptr) {
        VirtualPort::Impl& sender = *transmission.sender;
        settle_state(sender, change_counters(sender, transmit_error));
    }
    if (!ack_error) {
        for_each_receiver(transmission, nullptr, [this](VirtualPort::Impl& receiver) {
            return change_counters(receiver,
                                   [](ErrorCounters& counters) { counters.receive_error(); });
        });
    }
}

void VirtualBus::Impl::finish(bool next_in_line) {
    // What is left to do with the transmission, read before it goes (not copied whole).
    const std::size_t bits = current->timeline.bus_free;
    const std::size_t stuff_bits = current->length.stuff_bits;
    VirtualPort::Impl* const sender = current->sender;
    current.reset();
    stats.bits += bits;
    stats.stuff_bits += stuff_bits;
    stats.busy += bit * static_cast<std::int64_t>(bits);
    if (sender != nullptr && sender->counters.state() == ErrorState::Passive) {
        sender->suspended_until = at_bit(loop.now(), kSuspendTransmissionBits);
    }
    // The deferred arbitration would run next anyway when nothing else is due now: the frames
    // that compete are the same, and the bus saves an event per frame.
    if (next_in_line) {
        arbitrate();
    } else {
        request_arbitration();
    }
}

// --- fault confinement --------------------------------------------------------------------

void VirtualBus::Impl::change_state(VirtualPort::Impl& port, ErrorState before) {
    const ErrorState after = port.counters.state();
    // A bus-off controller receives nothing: its unvisited receptions stop counting meanwhile.
    if (after == ErrorState::BusOff) {
        port.counts.rx_frames += delivered + (settled(port) ? 1 : 0) - port.rx_base;
    } else if (before == ErrorState::BusOff) {
        port.rx_base = delivered + (settled(port) ? 1 : 0);
    }
    if (before == ErrorState::BusOff) {
        recovering_ports -= port.recovering ? 1 : 0;
        port.recovering = false;
        port.recovery_timer.cancel();
        if (port.next_frame() != nullptr) {
            request_arbitration();
        }
    }
    if (after == ErrorState::BusOff && config.bus_off_recovery == BusOffRecovery::Automatic) {
        start_recovery(port);
    }
    port.notify(after); // last: the handler may even destroy the port
}

void VirtualBus::Impl::start_recovery(VirtualPort::Impl& port) {
    recovering_ports += port.recovering ? 0 : 1;
    port.recovering = true;
    port.counting_from = loop.now();
    port.recessive_runs = 0;
    schedule_recovery(port);
}

// A recovering controller counts the runs of 11 recessive bits in each stretch of recessive
// bus that ends with a start of frame; the stretch in progress decides when it is done.
void VirtualBus::Impl::count_recessive_runs(VirtualPort::Impl& controller,
                                            core::TimePoint stretch_start,
                                            core::TimePoint start_of_frame) const {
    const core::Duration run = bit * static_cast<std::int64_t>(kRecessiveRunBits);
    const core::TimePoint from = std::max(stretch_start, controller.counting_from);
    if (start_of_frame > from) {
        controller.recessive_runs += static_cast<std::uint64_t>((start_of_frame - from) / run);
    }
}

void VirtualBus::Impl::schedule_recovery(VirtualPort::Impl& port) {
    const std::uint64_t missing =
        kBusOffRecoveryRuns - std::min(port.recessive_runs, kBusOffRecoveryRuns);
    const core::TimePoint done =
        at_bit(std::max(recessive_since, port.counting_from), missing * kRecessiveRunBits);
    port.recovery_timer = core::ScopedTimer(loop, loop.at(done, [this, &port] {
        const ErrorState before = port.counters.state();
        port.counters.reset();
        refresh_attention(port);
        settle_state(port, before);
    }));
}

// --- public interface ---------------------------------------------------------------------

VirtualBus::VirtualBus(core::EventLoop& loop, BusConfig config)
    : loop_(loop), config_(std::move(config)),
      impl_(std::make_unique<Impl>(loop, validated(config_))) {}

void VirtualBus::set_bitrate(std::uint32_t bitrate) {
    BusConfig changed = config_;
    changed.bitrate = bitrate;
    validated(changed);
    config_.bitrate = bitrate;
    impl_->bit = bit_duration(bitrate);
}

VirtualBus::~VirtualBus() {
    for (VirtualPort* port : impl_->ports) {
        if (port != nullptr) {
            port->impl_->counts.rx_frames += impl_->unvisited_receptions(*port->impl_);
            port->bus_ = nullptr;
            port->impl_->recovery_timer.cancel();
        }
    }
}

std::unique_ptr<VirtualPort> VirtualBus::connect(std::string name,
                                                 std::optional<std::size_t> tx_queue_capacity) {
    std::unique_ptr<VirtualPort> port(new VirtualPort(
        *this, std::move(name), tx_queue_capacity.value_or(config_.tx_queue_capacity)));
    impl_->attach(*port);
    return port;
}

core::Duration VirtualBus::bit_time() const {
    return impl_->bit;
}

BusStatistics VirtualBus::statistics() const {
    BusStatistics stats = impl_->stats;
    stats.elapsed = loop_.now() - impl_->created;
    return stats;
}

double BusStatistics::load() const {
    if (elapsed <= core::Duration::zero()) {
        return 0.0;
    }
    return static_cast<double>(busy.count()) / static_cast<double>(elapsed.count());
}

VirtualBus::ObserverId VirtualBus::add_observer(Observer observer) {
    const ObserverId id = impl_->next_observer++;
    impl_->observers.emplace(id, std::move(observer));
    return id;
}

void VirtualBus::remove_observer(ObserverId id) {
    const auto entry = impl_->observers.find(id);
    if (entry == impl_->observers.end()) {
        return;
    }
    if (impl_->notifying) {
        entry->second = nullptr;
    } else {
        impl_->observers.erase(entry);
    }
}

VirtualBus::FaultId VirtualBus::drop_frames(FrameFilter filter, std::uint64_t count) {
    return impl_->faults.add(FrameFault::Drop, std::move(filter), count);
}

VirtualBus::FaultId VirtualBus::corrupt_frames(FrameFilter filter, std::uint64_t count) {
    return impl_->faults.add(FrameFault::Corrupt, std::move(filter), count);
}

VirtualBus::FaultId VirtualBus::shorten_frames(FrameFilter filter, std::uint64_t count) {
    return impl_->faults.add(FrameFault::Shorten, std::move(filter), count);
}

bool VirtualBus::cancel_fault(FaultId id) {
    return impl_->faults.cancel(id);
}

} // namespace eposp::can
