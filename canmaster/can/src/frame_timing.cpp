#include "eposp/can/frame_timing.hpp"

#include <array>
#include <cassert>
#include <span>

namespace eposp::can {
namespace {

constexpr std::uint16_t kCrc15Polynomial = 0x4599;
constexpr std::uint16_t kCrc15Mask = 0x7FFF;
constexpr std::size_t kStuffRun = 5;
constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;

struct BitWriter {
    BitSequence bits;
    void append(std::uint32_t value, unsigned width) {
        for (unsigned bit = width; bit-- > 0;) {
            bits.push_back(((value >> bit) & 1U) != 0);
        }
    }
};

/// SOF, arbitration, control and data field (10.4.2): everything the CRC covers.
template <typename Writer>
void append_frame_fields(Writer& bits, const Frame& frame) {
    assert(frame.valid());
    constexpr unsigned dominant = 0;
    constexpr unsigned recessive = 1;
    const unsigned rtr = frame.remote ? recessive : dominant;
    bits.append(dominant, 1); // SOF
    if (frame.extended) {
        // 10.4.2.3: base identifier, SRR, IDE, identifier extension, RTR; then r1, r0.
        bits.append(frame.id >> 18, 11);
        bits.append(recessive, 1); // SRR
        bits.append(recessive, 1); // IDE
        bits.append(frame.id & 0x3FFFF, 18);
        bits.append(rtr, 1);
        bits.append(dominant, 1); // r1
    } else {
        bits.append(frame.id, 11);
        bits.append(rtr, 1);
        bits.append(dominant, 1); // IDE
    }
    bits.append(dominant, 1); // r0
    bits.append(frame.dlc, 4);
    for (const std::uint8_t byte : frame.payload()) {
        bits.append(byte, 8);
    }
}

constexpr std::uint16_t crc15_step(std::uint16_t crc, bool bit) {
    const bool feedback = bit != (((crc >> 14) & 1U) != 0);
    crc = static_cast<std::uint16_t>((crc << 1) & kCrc15Mask);
    return feedback ? static_cast<std::uint16_t>(crc ^ kCrc15Polynomial) : crc;
}

/// The stuffing state after some bits: the last bit sent (stuff bits included) and how many
/// equal bits end the output, 1 ... 4 (0 before the first bit). Encoded as last * 5 + run.
struct StuffState {
    bool last = false;
    unsigned run = 0;

    constexpr unsigned code() const { return (last ? 5U : 0U) + run; }
    /// Sends one bit; returns whether a stuff bit followed it (10.5).
    constexpr bool send(bool bit) {
        run = (run > 0 && bit == last) ? run + 1 : 1;
        last = bit;
        if (run == kStuffRun) {
            last = !bit;
            run = 1;
            return true;
        }
        return false;
    }
};
} // namespace

std::uint16_t crc15(const BitSequence& bits) {
    std::uint16_t crc = 0;
    for (std::size_t i = 0; i < bits.size(); ++i) {
        crc = crc15_step(crc, bits[i]);
    }
    return crc;
}

BitSequence unstuffed_bits(const Frame& frame) {
    BitWriter writer;
    append_frame_fields(writer, frame);
    writer.append(crc15(writer.bits), 15);
    return writer.bits;
}

StuffedBits stuff(const BitSequence& bits) {
    StuffedBits out;
    StuffState state;
    for (std::size_t i = 0; i < bits.size(); ++i) {
        out.bits.push_back(bits[i]);
        if (state.send(bits[i])) {
            out.bits.push_back(state.last);
            ++out.stuff_bits;
        }
    }
    return out;
}

namespace {

// frame_length() runs for every frame the virtual bus carries, so it works a byte at a time:
// the bits are packed into bytes, the CRC and the stuffing are table-driven. The test checks it
// against the bit-level stuff(unstuffed_bits()).

/// The bits in wire order, most significant first: whole bytes, then fewer than 8 tail bits.
class PackedBits {
public:
    void append(std::uint32_t value, unsigned width) {
        accumulator_ = (accumulator_ << width) | (value & ((std::uint64_t{1} << width) - 1));
        tail_bits_ += width;
        while (tail_bits_ >= 8) {
            tail_bits_ -= 8;
            bytes_[size_++] = static_cast<std::uint8_t>(accumulator_ >> tail_bits_);
        }
    }
    std::span<const std::uint8_t> bytes() const { return {bytes_.data(), size_}; }
    unsigned tail_bits() const { return tail_bits_; }
    /// Tail bit `i` (0 = the first of the tail).
    bool tail_bit(unsigned i) const { return ((accumulator_ >> (tail_bits_ - 1 - i)) & 1U) != 0; }

private:
    std::array<std::uint8_t, (kMaxUnstuffedBits + 7) / 8> bytes_{};
    std::size_t size_ = 0;
    std::uint64_t accumulator_ = 0;
    unsigned tail_bits_ = 0;
};

// CRC-15 eight bits at a time: entry b is the register b << 7 after eight steps with zero input.
constexpr std::array<std::uint16_t, 256> kCrc15Table = [] {
    std::array<std::uint16_t, 256> table{};
    for (unsigned byte = 0; byte < 256; ++byte) {
        auto crc = static_cast<std::uint16_t>(byte << 7);
        for (int bit = 0; bit < 8; ++bit) {
            crc = crc15_step(crc, false);
        }
        table[byte] = crc;
    }
    return table;
}();

std::uint16_t packed_crc15(const PackedBits& bits) {
    std::uint16_t crc = 0;
    for (const std::uint8_t byte : bits.bytes()) {
        crc = static_cast<std::uint16_t>(((crc << 8) & kCrc15Mask) ^
                                         kCrc15Table[((crc >> 7) ^ byte) & 0xFFU]);
    }
    for (unsigned i = 0; i < bits.tail_bits(); ++i) {
        crc = crc15_step(crc, bits.tail_bit(i));
    }
    return crc;
}

// unstuffed_bits(), packed.
PackedBits packed_unstuffed_bits(const Frame& frame) {
    PackedBits bits;
    append_frame_fields(bits, frame);
    bits.append(packed_crc15(bits), 15);
    return bits;
}

constexpr unsigned kStuffStates = 10;

/// Per state and byte: the state after the byte (low 4 bits) and the stuff bits it took.
constexpr std::array<std::uint8_t, kStuffStates* 256> kStuffTable = [] {
    std::array<std::uint8_t, kStuffStates * 256> table{};
    for (unsigned code = 0; code < kStuffStates; ++code) {
        for (unsigned byte = 0; byte < 256; ++byte) {
            StuffState state{.last = code >= 5, .run = code % 5};
            unsigned stuffed = 0;
            for (unsigned bit = 8; bit-- > 0;) {
                stuffed += state.send(((byte >> bit) & 1U) != 0) ? 1U : 0U;
            }
            table[code * 256 + byte] = static_cast<std::uint8_t>(state.code() | stuffed << 4);
        }
    }
    return table;
}();

} // namespace

FrameLength frame_length(const Frame& frame) {
    const PackedBits bits = packed_unstuffed_bits(frame);
    std::size_t stuff_bits = 0;
    unsigned code = 0;
    for (const std::uint8_t byte : bits.bytes()) {
        const std::uint8_t entry = kStuffTable[code * 256 + byte];
        code = entry & 0x0FU;
        stuff_bits += entry >> 4;
    }
    StuffState state{.last = code >= 5, .run = code % 5};
    for (unsigned i = 0; i < bits.tail_bits(); ++i) {
        stuff_bits += state.send(bits.tail_bit(i)) ? 1U : 0U;
    }
    const std::size_t unstuffed = bits.bytes().size() * 8 + bits.tail_bits();
    return {.stuffed = unstuffed + stuff_bits,
            .stuff_bits = stuff_bits,
            // The run that ends the output is the trailing one; recessive bits are 1.
            .trailing_recessive = state.last ? state.run : 0};
}

core::Duration bit_duration(std::uint32_t bitrate) {
    assert(bitrate > 0 && kNanosecondsPerSecond % bitrate == 0);
    return core::Duration(kNanosecondsPerSecond / bitrate);
}

core::Duration frame_duration(const Frame& frame, std::uint32_t bitrate) {
    return bit_duration(bitrate) * static_cast<std::int64_t>(frame_length(frame).total());
}

} // namespace eposp::can
