#include "eposp/can/io/socketcan_error_frame.hpp"

#include <linux/can/error.h>

namespace eposp::can::io {

std::optional<ErrorState> error_state_reported_by(const Frame& error_frame) {
    if (!error_frame.error) {
        return std::nullopt;
    }
    if (error_frame.id & CAN_ERR_BUSOFF) {
        return ErrorState::BusOff;
    }
    if (error_frame.id & CAN_ERR_RESTARTED) {
        return ErrorState::Active;
    }
    if (error_frame.id & CAN_ERR_CRTL) {
        const std::uint8_t controller = error_frame.data[1];
        if (controller & (CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE)) {
            return ErrorState::Passive;
        }
        // The kernel reports a controller that recovers with the level it fell back to.
        if (controller & (CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING)) {
            return ErrorState::Warning;
        }
        if (controller & CAN_ERR_CRTL_ACTIVE) {
            return ErrorState::Active;
        }
    }
    return std::nullopt;
}

} // namespace eposp::can::io
