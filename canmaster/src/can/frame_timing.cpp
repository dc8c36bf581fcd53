#include "eposp/canmaster/can/frame_timing.hpp"

#include <cassert>

namespace eposp::can {
namespace {

constexpr std::uint16_t kCrc15Polynomial = 0x4599;
constexpr std::uint16_t kCrc15Mask = 0x7FFF;
constexpr std::size_t kStuffRun = 5;
constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;

void append(BitSequence& bits, std::uint32_t value, unsigned width) {
    for (unsigned bit = width; bit-- > 0;) {
        bits.push_back(((value >> bit) & 1U) != 0);
    }
}

} // namespace

std::uint16_t crc15(const BitSequence& bits) {
    std::uint16_t crc = 0;
    for (std::size_t i = 0; i < bits.size(); ++i) {
        const bool feedback = bits[i] != (((crc >> 14) & 1U) != 0);
        crc = static_cast<std::uint16_t>((crc << 1) & kCrc15Mask);
        if (feedback) {
            crc ^= kCrc15Polynomial;
        }
    }
    return crc;
}

BitSequence unstuffed_bits(const Frame& frame) {
    assert(frame.valid());
    constexpr bool dominant = false;
    constexpr bool recessive = true;
    BitSequence bits;
    bits.push_back(dominant); // SOF
    if (frame.extended) {
        // 10.4.2.3: base identifier, SRR, IDE, identifier extension, RTR; then r1, r0.
        append(bits, frame.id >> 18, 11);
        bits.push_back(recessive); // SRR
        bits.push_back(recessive); // IDE
        append(bits, frame.id & 0x3FFFF, 18);
        bits.push_back(frame.remote);
        bits.push_back(dominant); // r1
    } else {
        append(bits, frame.id, 11);
        bits.push_back(frame.remote);
        bits.push_back(dominant); // IDE
    }
    bits.push_back(dominant); // r0
    append(bits, frame.dlc, 4);
    for (const std::uint8_t byte : frame.payload()) {
        append(bits, byte, 8);
    }
    append(bits, crc15(bits), 15);
    return bits;
}

StuffedBits stuff(const BitSequence& bits) {
    StuffedBits out;
    std::size_t run = 0;
    for (std::size_t i = 0; i < bits.size(); ++i) {
        const bool bit = bits[i];
        run = (out.bits.size() > 0 && out.bits.back() == bit) ? run + 1 : 1;
        out.bits.push_back(bit);
        if (run == kStuffRun) {
            out.bits.push_back(!bit);
            ++out.stuff_bits;
            run = 1;
        }
    }
    return out;
}

FrameLength frame_length(const Frame& frame) {
    const StuffedBits stuffed = stuff(unstuffed_bits(frame));
    FrameLength length{.stuffed = stuffed.bits.size(), .stuff_bits = stuffed.stuff_bits};
    while (length.trailing_recessive < length.stuffed &&
           stuffed.bits[length.stuffed - 1 - length.trailing_recessive]) {
        ++length.trailing_recessive;
    }
    return length;
}

core::Duration bit_duration(std::uint32_t bitrate) {
    assert(bitrate > 0 && kNanosecondsPerSecond % bitrate == 0);
    return core::Duration(kNanosecondsPerSecond / bitrate);
}

core::Duration frame_duration(const Frame& frame, std::uint32_t bitrate) {
    return bit_duration(bitrate) * static_cast<std::int64_t>(frame_length(frame).total());
}

} // namespace eposp::can
