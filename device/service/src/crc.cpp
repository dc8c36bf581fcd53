#include "eposp/service/crc.hpp"

#include "eposp/service/frame_limits.hpp"

#include <boost/crc.hpp>
#include <stdexcept>

namespace eposp::service {
namespace {

// CRC-CCITT, MSB first, initial value 0, no final XOR (Boost's own crc_xmodem_type is the
// reflected variant, which is not this one).
using CrcCcitt = boost::crc_optimal<16, 0x1021, 0, 0, false, false>;

// Feeds a word high byte first, as maxon's word-wise algorithm shifts it in.
void feed_word(CrcCcitt& crc, std::uint16_t word) {
    crc.process_byte(static_cast<std::uint8_t>(word >> 8));
    crc.process_byte(static_cast<std::uint8_t>(word));
}

} // namespace

std::uint16_t frame_crc(std::uint16_t first_word, std::span<const std::uint8_t> data) {
    if (data.size() % 2 != 0) {
        throw std::invalid_argument("a frame's data is whole 16-bit words");
    }
    // maxon's CalcFieldCRC shifts each bit in at the bottom and ends with a 0x0000 word: that
    // trailing word is the augmentation of the plain (non-augmented) CRC, so the table-driven
    // CRC-CCITT over the words without it gives the same value (checked by the guide's vectors).
    CrcCcitt crc;
    feed_word(crc, first_word);
    for (std::size_t at = 0; at < data.size(); at += 2) {
        feed_word(crc, static_cast<std::uint16_t>(data[at] | data[at + 1] << 8));
    }
    return static_cast<std::uint16_t>(crc.checksum());
}

std::uint16_t v1_crc(const Frame& frame) {
    if (frame.words() < 1 || frame.words() > kV1MaxWords) {
        throw std::invalid_argument("a v1 frame holds 1 to 256 words");
    }
    const auto len_minus_one = static_cast<std::uint16_t>(frame.words() - 1);
    return frame_crc(static_cast<std::uint16_t>(frame.opcode << 8 | len_minus_one), frame.data);
}

std::uint16_t v2_crc(const Frame& frame) {
    if (frame.words() > kV2MaxWords) {
        throw std::invalid_argument("a v2 frame holds at most 255 words");
    }
    const auto len = static_cast<std::uint16_t>(frame.words());
    return frame_crc(static_cast<std::uint16_t>(len << 8 | frame.opcode), frame.data);
}

} // namespace eposp::service
