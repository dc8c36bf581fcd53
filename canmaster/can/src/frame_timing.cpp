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

// frame_length() runs for every frame the virtual bus carries, so it takes the bits in chunks:
// the CRC and the stuffing are table-driven. The test checks it against the bit-level
// stuff(unstuffed_bits()).

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

constexpr unsigned kStuffStates = 10;

/// Per stuffing state and chunk of `Bits` bits: the state after the chunk and the stuff bits it
/// took, as (state << 8) | stuff bits. The state is then already the row offset of the 8-bit
/// table, and the entries of a frame add up to its stuff bits in the low byte (fewer than 256).
template <unsigned Bits>
constexpr std::array<std::uint16_t, (kStuffStates << Bits)> stuff_table() {
    std::array<std::uint16_t, (kStuffStates << Bits)> table{};
    for (unsigned code = 0; code < kStuffStates; ++code) {
        for (unsigned chunk = 0; chunk < (1U << Bits); ++chunk) {
            StuffState state{.last = code >= 5, .run = code % 5};
            unsigned stuffed = 0;
            for (unsigned bit = Bits; bit-- > 0;) {
                stuffed += state.send(((chunk >> bit) & 1U) != 0) ? 1U : 0U;
            }
            table[(code << Bits) + chunk] = static_cast<std::uint16_t>(state.code() << 8 | stuffed);
        }
    }
    return table;
}
constexpr auto kStuffTable8 = stuff_table<8>();
/// The odd chunks ahead of whole bytes: a standard header (19 bits), an extended header (39)
/// and the CRC sequence (15).
constexpr auto kStuffTable7 = stuff_table<7>();
constexpr auto kStuffTable3 = stuff_table<3>();

/// CRC-15 sixteen bits at a time. Sixteen bits M into the register R leave (R * x^16 + M * x^15)
/// mod the generator, that is V * x^15 with V = (R << 1) ^ M: one entry for each byte of V.
constexpr std::uint16_t crc15_of_16_bits(std::uint32_t bits) {
    std::uint16_t crc = 0;
    for (int bit = 15; bit >= 0; --bit) {
        crc = crc15_step(crc, ((bits >> bit) & 1U) != 0);
    }
    return crc;
}
template <unsigned Shift>
constexpr std::array<std::uint16_t, 256> crc15_word_table() {
    std::array<std::uint16_t, 256> table{};
    for (unsigned byte = 0; byte < 256; ++byte) {
        table[byte] = crc15_of_16_bits(byte << Shift);
    }
    return table;
}
constexpr auto kCrc15HighByte = crc15_word_table<8>();
constexpr auto kCrc15LowByte = crc15_word_table<0>();

/// The CRC register over the bits the CRC covers, taken as whole bytes with zeros ahead: zeros
/// leave a register of 0 unchanged.
class Crc15 {
public:
    void word(std::uint32_t bits) {
        const std::uint32_t v = ((crc_ << 1) ^ bits) & 0xFFFFU;
        crc_ = static_cast<std::uint16_t>(kCrc15HighByte[v >> 8] ^ kCrc15LowByte[v & 0xFFU]);
    }
    void byte(std::uint32_t bits) {
        crc_ = static_cast<std::uint16_t>(
            ((crc_ << 8) ^ kCrc15Table[((crc_ >> 7) ^ bits) & 0xFFU]) & kCrc15Mask);
    }
    std::uint16_t value() const { return crc_; }

private:
    std::uint16_t crc_ = 0;
};

constexpr unsigned kStateMask = 0x0F00;

/// The stuffing state over the bits sent so far, a chunk at a time.
class Stuffing {
public:
    void bits3(std::uint32_t chunk) { take(kStuffTable3[((state_ >> 8) << 3) + (chunk & 0x7U)]); }
    void bits7(std::uint32_t chunk) { take(kStuffTable7[((state_ >> 8) << 7) + (chunk & 0x7FU)]); }
    void bits8(std::uint32_t chunk) { take(kStuffTable8[state_ + (chunk & 0xFFU)]); }

    /// `sent`: the bits sent, before stuffing.
    FrameLength length(std::size_t sent) const {
        const unsigned code = state_ >> 8;
        const std::size_t stuff_bits = entries_ & 0xFFU;
        return {.stuffed = sent + stuff_bits,
                .stuff_bits = stuff_bits,
                // The run that ends the output is the trailing one; recessive bits are 1.
                .trailing_recessive = code >= 5 ? code % 5 : 0};
    }

private:
    void take(std::uint16_t entry) {
        state_ = entry & kStateMask;
        entries_ += entry;
    }

    unsigned state_ = 0;   ///< StuffState::code() << 8: the row of the 8-bit table
    unsigned entries_ = 0; ///< the sum of the table entries taken: the stuff bits in its low byte
};

} // namespace

// The fields of append_frame_fields() packed into one word: SOF and the arbitration and control
// fields are 19 bits in a standard frame (3 + 8 + 8 for the stuffing, 16 + 16 with zeros ahead
// for the CRC), 39 in an extended one (7 + 4 * 8; 8 + 16 + 16).
FrameLength frame_length(const Frame& frame) {
    assert(frame.valid());
    const std::uint64_t rtr = frame.remote ? 1 : 0;
    Stuffing stuffing;
    Crc15 crc;
    std::size_t header = 19;
    if (frame.extended) {
        // SOF 0, base identifier, SRR 1, IDE 1, identifier extension, RTR, r1 0, r0 0, DLC.
        header = 39;
        const std::uint64_t bits = std::uint64_t{frame.id >> 18} << 27 | std::uint64_t{3} << 25 |
                                   std::uint64_t{frame.id & 0x3FFFF} << 7 | rtr << 6 | frame.dlc;
        stuffing.bits7(static_cast<std::uint32_t>(bits >> 32));
        stuffing.bits8(static_cast<std::uint32_t>(bits >> 24));
        stuffing.bits8(static_cast<std::uint32_t>(bits >> 16));
        stuffing.bits8(static_cast<std::uint32_t>(bits >> 8));
        stuffing.bits8(static_cast<std::uint32_t>(bits));
        crc.byte(static_cast<std::uint32_t>(bits >> 32));
        crc.word(static_cast<std::uint32_t>(bits >> 16));
        crc.word(static_cast<std::uint32_t>(bits));
    } else {
        // SOF 0, identifier, RTR, IDE 0, r0 0, DLC.
        const std::uint32_t bits = frame.id << 7 | static_cast<std::uint32_t>(rtr) << 6 | frame.dlc;
        stuffing.bits3(bits >> 16);
        stuffing.bits8(bits >> 8);
        stuffing.bits8(bits);
        crc.word(bits >> 16);
        crc.word(bits);
    }
    const std::span<const std::uint8_t> payload = frame.payload();
    const std::size_t n = payload.size();
    for (std::size_t i = 0; i + 1 < n; i += 2) {
        stuffing.bits8(payload[i]);
        stuffing.bits8(payload[i + 1]);
        crc.word(std::uint32_t{payload[i]} << 8 | payload[i + 1]);
    }
    if (n % 2 != 0) {
        stuffing.bits8(payload[n - 1]);
        crc.byte(payload[n - 1]);
    }
    stuffing.bits7(crc.value() >> 8U);
    stuffing.bits8(crc.value());
    return stuffing.length(header + 8 * n + 15);
}

core::Duration bit_duration(std::uint32_t bitrate) {
    assert(bitrate > 0 && kNanosecondsPerSecond % bitrate == 0);
    return core::Duration(kNanosecondsPerSecond / bitrate);
}

core::Duration frame_duration(const Frame& frame, std::uint32_t bitrate) {
    return bit_duration(bitrate) * static_cast<std::int64_t>(frame_length(frame).total());
}

} // namespace eposp::can
