#include "eposp/can/error_frame.hpp"

#include <algorithm>

namespace eposp::can {
namespace {

using err::ErrorLocation;

std::uint8_t clamp_to_byte(unsigned value) {
    return static_cast<std::uint8_t>(std::min(value, 255U));
}

Frame bus_error_frame(std::uint32_t classes, std::uint8_t type, ErrorLocation location,
                      const ErrorCounters& counters, bool state_changed) {
    Frame frame;
    frame.error = true;
    frame.dlc = kMaxDataLength; // CAN_ERR_DLC
    frame.id = err::kProtocol | err::kBusError | err::kCounters | classes;
    frame.data[err::kProtocolTypeByte] = type | err::kOnTransmission;
    frame.data[err::kLocationByte] = static_cast<std::uint8_t>(location);
    frame.data[err::kTransmitCounterByte] = clamp_to_byte(counters.transmit());
    frame.data[err::kReceiveCounterByte] = clamp_to_byte(counters.receive());
    if (state_changed && counters.state() == ErrorState::BusOff) {
        frame.id |= err::kBusOff;
    } else if (state_changed && counters.state() == ErrorState::Passive) {
        frame.id |= err::kController;
        frame.data[err::kControllerByte] = static_cast<std::uint8_t>(
            (counters.transmit() > kErrorPassiveAbove ? err::kTxPassive : 0) |
            (counters.receive() > kErrorPassiveAbove ? err::kRxPassive : 0));
    } else if (state_changed && counters.state() == ErrorState::Warning) {
        frame.id |= err::kController;
        frame.data[err::kControllerByte] = static_cast<std::uint8_t>(
            (counters.transmit() >= kErrorWarningFrom ? err::kTxWarning : 0) |
            (counters.receive() >= kErrorWarningFrom ? err::kRxWarning : 0));
    }
    return frame;
}

} // namespace

Frame crc_sequence_bit_error_frame(bool sent_recessive, const ErrorCounters& counters,
                                   bool state_changed) {
    return bus_error_frame(0, sent_recessive ? err::kBit1 : err::kBit0, ErrorLocation::CrcSequence,
                           counters, state_changed);
}

Frame ack_error_frame(const ErrorCounters& counters, bool state_changed) {
    return bus_error_frame(err::kNoAck, 0, ErrorLocation::AckSlot, counters, state_changed);
}

} // namespace eposp::can
