#pragma once

#include "eposp/can/error_counters.hpp"
#include "eposp/can/frame.hpp"

#include <cstddef>
#include <cstdint>

namespace eposp::can {

/// Error frames in SocketCAN form (linux/can/error.h): the error classes are bits of
/// Frame::id, the details are in the 8 data bytes. The virtual bus reports every error as a
/// bus error seen by the transmitter (CAN_ERR_PROT | CAN_ERR_BUSERROR, with CAN_ERR_PROT_TX),
/// carries its error counters after the error (CAN_ERR_CNT) and, when the error changed its
/// state, CAN_ERR_CRTL with the passive flags or CAN_ERR_BUSOFF.
namespace err {

// Classes: Frame::id of an error frame.
inline constexpr std::uint32_t kController = 0x004; ///< CAN_ERR_CRTL: details in data[1]
inline constexpr std::uint32_t kProtocol = 0x008;   ///< CAN_ERR_PROT: details in data[2..3]
inline constexpr std::uint32_t kNoAck = 0x020;      ///< CAN_ERR_ACK: no ACK on transmission
inline constexpr std::uint32_t kBusOff = 0x040;     ///< CAN_ERR_BUSOFF
inline constexpr std::uint32_t kBusError = 0x080;   ///< CAN_ERR_BUSERROR
inline constexpr std::uint32_t kCounters = 0x200;   ///< CAN_ERR_CNT: counters in data[6..7]

// Where the details are.
inline constexpr std::size_t kControllerByte = 1;
inline constexpr std::size_t kProtocolTypeByte = 2;
inline constexpr std::size_t kLocationByte = 3;
inline constexpr std::size_t kTransmitCounterByte = 6;
inline constexpr std::size_t kReceiveCounterByte = 7;

// data[1]: controller state.
inline constexpr std::uint8_t kRxWarning = 0x04; ///< CAN_ERR_CRTL_RX_WARNING
inline constexpr std::uint8_t kTxWarning = 0x08; ///< CAN_ERR_CRTL_TX_WARNING
inline constexpr std::uint8_t kRxPassive = 0x10; ///< CAN_ERR_CRTL_RX_PASSIVE
inline constexpr std::uint8_t kTxPassive = 0x20; ///< CAN_ERR_CRTL_TX_PASSIVE

// data[2]: protocol error type.
inline constexpr std::uint8_t kBit0 = 0x08; ///< CAN_ERR_PROT_BIT0: sent dominant, saw recessive
inline constexpr std::uint8_t kBit1 = 0x10; ///< CAN_ERR_PROT_BIT1: sent recessive, saw dominant
inline constexpr std::uint8_t kOnTransmission = 0x80; ///< CAN_ERR_PROT_TX

/// data[3]: where in the frame the error was detected (CAN_ERR_PROT_LOC_*, the SJA1000's
/// error code capture segments).
enum class ErrorLocation : std::uint8_t {
    CrcSequence = 0x08,
    AckSlot = 0x19,
};

} // namespace err

/// A bit error in the CRC sequence: the transmitter read back the other level than it sent,
/// `sent_recessive` says which. `counters` are its counters after the error; `state_changed`
/// says whether the error changed its state.
Frame crc_sequence_bit_error_frame(bool sent_recessive, const ErrorCounters& counters,
                                   bool state_changed);

/// No receiver acknowledged the transmitter's frame (ACK error in the ACK slot).
Frame ack_error_frame(const ErrorCounters& counters, bool state_changed);

} // namespace eposp::can
