#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/can/port.hpp"

#include <optional>

namespace eposp::can::io {

/// The fault confinement state that a SocketCAN error frame announces (linux/can/error.h):
/// bus-off, a controller that reached or left error-passive, or a restart after bus-off.
/// `error_frame.id` holds the error class bits and `data` the details, as the kernel sends
/// them. Nothing when the frame reports something else (a protocol violation, a lost
/// arbitration, a missing ACK).
std::optional<ErrorState> error_state_reported_by(const Frame& error_frame);

} // namespace eposp::can::io
