#pragma once

#include "eposp/can/port.hpp"

namespace eposp::can {

/// A counter at this or above is the error warning level (ISO 11898-1 leaves it to the
/// implementation; 96 is what CAN controllers and SocketCAN use).
inline constexpr unsigned kErrorWarningFrom = 96;
/// A counter above this makes a controller error-passive.
inline constexpr unsigned kErrorPassiveAbove = 127;
/// A transmit error counter above this makes it bus-off.
inline constexpr unsigned kBusOffAbove = 255;

/// A controller's transmit and receive error counters and the fault confinement state they
/// imply (ISO 11898-1:2015, 12.1.4): the warning level from 96, error-passive when a counter is
/// above 127, bus-off when the transmit error counter is above 255. The bus applies the rules;
/// this class does the arithmetic.
class ErrorCounters {
public:
    unsigned transmit() const { return transmit_; }
    unsigned receive() const { return receive_; }
    /// Kept with the counters: the bus asks for it several times per port and frame.
    ErrorState state() const { return state_; }

    /// A transmitter that sends an error flag adds 8. The exception: an error-passive
    /// transmitter that detects an ACK error (and no dominant bit in its passive error flag)
    /// leaves the counter as it is, so a node alone on a bus ends error-passive, not bus-off.
    void transmit_error(bool ack_error);
    /// A receiver that detects an error adds 1.
    void receive_error();
    /// A frame transmitted successfully subtracts 1.
    void transmit_success();
    /// A frame received successfully subtracts 1; from above 127 the counter drops
    /// to a value between 119 and 127 (we take 119). Inline: every port, every frame.
    void receive_success() {
        if (receive_ != 0) { // else the common case: nothing to count down
            count_down_receive();
        }
    }

    /// Bus-off recovery completed: both counters start again from 0.
    void reset();
    /// Fault injection: the counters of the first moment in `state` (0/0, TEC 128, TEC 256).
    void force(ErrorState state);

private:
    void update_state();
    void count_down_receive();

    unsigned transmit_ = 0;
    unsigned receive_ = 0;
    ErrorState state_ = ErrorState::Active;
};

} // namespace eposp::can
