#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/core/time.hpp"

#include <bitset>
#include <cstddef>
#include <cstdint>

namespace eposp::can {

// The bit math of a classic CAN frame on the wire (ISO 11898-1:2015, 10.4 frame formats and
// 10.5 frame coding). Pure functions: the virtual bus takes its frame times from here.

/// SOF through the CRC sequence of an extended data frame with 8 bytes: the longest part of
/// any frame that bit stuffing covers.
inline constexpr std::size_t kMaxUnstuffedBits = 1 + 32 + 6 + 64 + 15;
/// One stuff bit after the first 5 bits, then at most one after every 4 more.
inline constexpr std::size_t kMaxStuffedBits = kMaxUnstuffedBits + (kMaxUnstuffedBits - 1) / 4;

/// CRC delimiter, ACK slot, ACK delimiter and the 7 bits of EOF: the fixed-form tail of a data
/// or remote frame, which is not stuffed.
inline constexpr std::size_t kFrameTailBits = 1 + 2 + 7;
/// Intermission (10.4.6): 3 recessive bits before the bus is idle again.
inline constexpr std::size_t kIntermissionBits = 3;
/// Error flag (10.4.4.2), as long as one node's flag when all nodes detect the error at the
/// same bit.
inline constexpr std::size_t kErrorFlagBits = 6;
/// Error delimiter (10.4.4.3): 8 recessive bits.
inline constexpr std::size_t kErrorDelimiterBits = 8;
/// Suspend transmission (10.4.6): an error-passive transmitter waits this many extra bits.
inline constexpr std::size_t kSuspendTransmissionBits = 8;
/// Bus-off recovery (12.1.4.2) counts occurrences of this many consecutive recessive bits.
inline constexpr std::size_t kRecessiveRunBits = 11;

/// A short sequence of bits in wire order; `true` is a recessive bit (logical 1).
class BitSequence {
public:
    void push_back(bool bit) { bits_[size_++] = bit; }
    bool operator[](std::size_t index) const { return bits_[index]; }
    std::size_t size() const { return size_; }
    bool back() const { return bits_[size_ - 1]; }
    friend bool operator==(const BitSequence&, const BitSequence&) = default;

private:
    std::bitset<kMaxStuffedBits> bits_;
    std::size_t size_ = 0;
};

/// CRC-15 of ISO 11898-1 (10.4.2.6), generator polynomial 0x4599, register initially 0, over
/// the given bits in order.
std::uint16_t crc15(const BitSequence& bits);

/// SOF, arbitration, control and data field, then the CRC sequence: the frame's bits before
/// stuffing. `frame` must be valid().
BitSequence unstuffed_bits(const Frame& frame);

/// The bits as sent: after 5 consecutive equal bits a complementary stuff bit, which itself
/// counts towards the next run (10.5).
struct StuffedBits {
    BitSequence bits;
    std::size_t stuff_bits = 0;
};
StuffedBits stuff(const BitSequence& bits);

/// A frame's length on the wire in bits, stuff bits included.
struct FrameLength {
    std::size_t stuffed = 0;    ///< SOF .. end of CRC sequence, stuff bits included
    std::size_t stuff_bits = 0; ///< stuff bits among them
    /// Trailing recessive bits of the stuffed part: with the tail they start the recessive
    /// run that bus-off recovery counts.
    std::size_t trailing_recessive = 0;

    /// Up to the end of EOF: the instant a receiver takes the frame.
    std::size_t to_end_of_frame() const { return stuffed + kFrameTailBits; }
    /// Including the intermission: the bit times the bus is busy.
    std::size_t total() const { return to_end_of_frame() + kIntermissionBits; }
};
FrameLength frame_length(const Frame& frame);

/// The duration of one bit; `bitrate` in bit/s must divide 10^9 ns.
core::Duration bit_duration(std::uint32_t bitrate);
/// The time `frame` keeps the bus busy, intermission included.
core::Duration frame_duration(const Frame& frame, std::uint32_t bitrate);

} // namespace eposp::can
