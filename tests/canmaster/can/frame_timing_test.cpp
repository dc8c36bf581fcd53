#include "eposp/can/frame_timing.hpp"

#include <gtest/gtest.h>
#include <random>
#include <string>
#include <string_view>

namespace eposp::can {
namespace {

using std::chrono::microseconds;
using std::chrono::nanoseconds;

BitSequence bits_from(std::string_view text) {
    BitSequence bits;
    for (const char c : text) {
        bits.push_back(c == '1');
    }
    return bits;
}

std::string text_of(const BitSequence& bits) {
    std::string text;
    for (std::size_t i = 0; i < bits.size(); ++i) {
        text += bits[i] ? '1' : '0';
    }
    return text;
}

TEST(FrameTiming, Crc15MatchesTheCatalogueCheckValue) {
    // CRC-15/CAN of the ASCII bytes "123456789", most significant bit first, is 0x059E.
    BitSequence bits;
    for (const char c : std::string_view("123456789")) {
        for (int bit = 7; bit >= 0; --bit) {
            bits.push_back(((static_cast<unsigned>(c) >> bit) & 1U) != 0);
        }
    }
    EXPECT_EQ(crc15(bits), 0x059E);
}

TEST(FrameTiming, StuffBitFollowsFiveEqualBits) {
    EXPECT_EQ(text_of(stuff(bits_from("0000")).bits), "0000");
    EXPECT_EQ(text_of(stuff(bits_from("00000")).bits), "000001");
    EXPECT_EQ(text_of(stuff(bits_from("111110")).bits), "1111100");
}

TEST(FrameTiming, StuffBitCountsTowardsTheNextRun) {
    // The stuff bit 1 and four data bits 1 make five equal bits: another stuff bit follows.
    const StuffedBits stuffed = stuff(bits_from("000001111"));
    EXPECT_EQ(text_of(stuffed.bits), "00000111110");
    EXPECT_EQ(stuffed.stuff_bits, 2U);
}

TEST(FrameTiming, AllDominantFrameHasAStuffBitAfterEveryFifthBit) {
    // Identifier 0, DLC 0: SOF, 11 identifier bits, RTR, IDE, r0, DLC and CRC (0) are 34
    // dominant bits, so a recessive stuff bit follows bits 5, 10, ... 30.
    const Frame frame = Frame::data_frame(0x000, {});
    EXPECT_EQ(crc15(unstuffed_bits(frame)), 0); // the CRC of the zero bits before the CRC
    const StuffedBits stuffed = stuff(unstuffed_bits(frame));
    EXPECT_EQ(text_of(stuffed.bits), "0000010000010000010000010000010000010000");
    EXPECT_EQ(stuffed.stuff_bits, 6U);

    const FrameLength length = frame_length(frame);
    EXPECT_EQ(length.stuffed, 40U);
    EXPECT_EQ(length.to_end_of_frame(), 50U);
    EXPECT_EQ(length.total(), 53U); // 47 + 8 * 0 bits unstuffed, 6 stuff bits
}

TEST(FrameTiming, StandardFrameBitsAreSofIdentifierControlDataCrc) {
    // 0x123 = 001 0010 0011, RTR 0, IDE 0, r0 0, DLC 0011, data 11 22 33, CRC 0x65ED.
    const Frame frame = Frame::data_frame(0x123, {0x11, 0x22, 0x33});
    EXPECT_EQ(text_of(unstuffed_bits(frame)), "0"
                                              "00100100011"
                                              "000"
                                              "0011"
                                              "000100010010001000110011"
                                              "110010111101101");
    EXPECT_EQ(frame_length(frame).stuff_bits, 1U); // after RTR, IDE, r0 and DLC "00"
    EXPECT_EQ(frame_length(frame).total(), 47U + 24U + 1U);
}

TEST(FrameTiming, EightZeroBytesStuffHeavily) {
    // 15 dominant header bits, DLC 1000, 64 dominant data bits, CRC 0x145B: 16 stuff bits.
    const Frame frame = Frame::data_frame(0x000, {0, 0, 0, 0, 0, 0, 0, 0});
    EXPECT_EQ(crc15(unstuffed_bits(frame)), 0); // a codeword: the CRC over it all is 0
    EXPECT_EQ(frame_length(frame).stuff_bits, 16U);
    EXPECT_EQ(frame_length(frame).total(), 47U + 64U + 16U);
}

TEST(FrameTiming, ExtendedFrameCarriesSrrIdeAndIdentifierExtension) {
    // 0x1FFFFFFF: base 0x7FF, SRR 1, IDE 1, extension 0x3FFFF, RTR 0, r1 0, r0 0, DLC 1000,
    // then 0xAA x 8 and CRC 0x7A58; the 33 recessive bits of SOF+1 ... RTR need 6 stuff bits.
    const Frame frame =
        Frame::data_frame(0x1FFFFFFF, {0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA, 0xAA}, true);
    const std::string bits = text_of(unstuffed_bits(frame));
    EXPECT_EQ(bits.substr(0, 39),
              "0" + std::string(11, '1') + "11" + std::string(18, '1') + "000" + "1000");
    EXPECT_EQ(bits.substr(bits.size() - 15), "111101001011000");
    const FrameLength length = frame_length(frame);
    EXPECT_EQ(length.stuff_bits, 6U);
    EXPECT_EQ(length.total(), 67U + 64U + 6U);
}

TEST(FrameTiming, RemoteFrameHasItsDlcButNoDataField) {
    // 0x701 = 111 0000 0001, RTR 1, IDE 0, r0 0, DLC 0001, CRC 0x79E0.
    const Frame frame = Frame::remote_frame(0x701, 1);
    EXPECT_EQ(text_of(unstuffed_bits(frame)), "0"
                                              "11100000001"
                                              "100"
                                              "0001"
                                              "111100111100000");
    EXPECT_EQ(frame_length(frame).stuff_bits, 4U);
    EXPECT_EQ(frame_length(frame).total(), 47U + 4U);
}

TEST(FrameTiming, TrailingRecessiveBitsOfTheCrcAreCounted) {
    EXPECT_EQ(frame_length(Frame::data_frame(0x000, {})).trailing_recessive, 0U);
    // 0x123 [11 22 33]: the CRC sequence ends in "01", and no stuff bit follows.
    EXPECT_EQ(frame_length(Frame::data_frame(0x123, {0x11, 0x22, 0x33})).trailing_recessive, 1U);
}

TEST(FrameTiming, DurationsAreExactAtEveryBitRate) {
    const Frame frame = Frame::data_frame(0x000, {}); // 53 bits
    EXPECT_EQ(bit_duration(1'000'000), nanoseconds(1000));
    EXPECT_EQ(frame_duration(frame, 1'000'000), microseconds(53));
    EXPECT_EQ(frame_duration(frame, 125'000), microseconds(53 * 8));
    EXPECT_EQ(frame_duration(frame, 10'000), microseconds(53 * 100));
    EXPECT_EQ(frame_duration(Frame::remote_frame(0x701, 1), 125'000), microseconds(51 * 8));
    EXPECT_EQ(frame_duration(Frame::data_frame(0x000, {0, 0, 0, 0, 0, 0, 0, 0}), 800'000),
              nanoseconds(127 * 1250));
}

// Known bounds: 47 + 8n bits before stuffing (67 + 8n extended), intermission included, and at
// most one stuff bit for the first 5 bits of SOF..CRC and then one per 4.
TEST(FrameTiming, RandomFramesStayWithinTheKnownBounds) {
    std::mt19937 random(1234);
    std::uniform_int_distribution<std::uint32_t> word;
    for (int i = 0; i < 20'000; ++i) {
        const bool extended = (i % 2) == 1;
        const std::uint8_t n = static_cast<std::uint8_t>(word(random) % 9);
        std::array<std::uint8_t, kMaxDataLength> data{};
        for (auto& byte : data) {
            byte = static_cast<std::uint8_t>(word(random));
        }
        const std::uint32_t id = word(random) & (extended ? kMaxExtendedId : kMaxStandardId);
        const Frame frame =
            Frame::data_frame(id, std::span<const std::uint8_t>(data.data(), n), extended);
        const std::size_t stuffable = (extended ? 54U : 34U) + 8U * n;
        const FrameLength length = frame_length(frame);
        ASSERT_EQ(length.total() - length.stuff_bits, stuffable + 13U);
        ASSERT_LE(length.stuff_bits, (stuffable - 1) / 4);
    }
}

// frame_length() packs the bits into words for speed; it must count exactly what the bit-level
// reference stuff(unstuffed_bits()) produces, remote frames and all-equal payloads included.
TEST(FrameTiming, FrameLengthMatchesTheBitLevelReference) {
    std::mt19937 random(4321);
    std::uniform_int_distribution<std::uint32_t> word;
    for (int i = 0; i < 20'000; ++i) {
        const bool extended = (i % 2) == 1;
        const auto n = static_cast<std::uint8_t>(word(random) % 9);
        std::array<std::uint8_t, kMaxDataLength> data{};
        const std::uint32_t fill = word(random) % 4; // 0 and 3: runs of equal bits
        for (auto& byte : data) {
            byte = static_cast<std::uint8_t>(fill == 0 ? 0x00 : fill == 3 ? 0xFF : word(random));
        }
        const std::uint32_t id = word(random) & (extended ? kMaxExtendedId : kMaxStandardId);
        const Frame frame = (i % 7) == 0
                                ? Frame::remote_frame(id, n, extended)
                                : Frame::data_frame(id, std::span(data.data(), n), extended);
        const StuffedBits reference = stuff(unstuffed_bits(frame));
        std::size_t trailing = 0;
        while (trailing < reference.bits.size() &&
               reference.bits[reference.bits.size() - 1 - trailing]) {
            ++trailing;
        }
        const FrameLength length = frame_length(frame);
        ASSERT_EQ(length.stuffed, reference.bits.size()) << i;
        ASSERT_EQ(length.stuff_bits, reference.stuff_bits) << i;
        ASSERT_EQ(length.trailing_recessive, trailing) << i;
    }
}

} // namespace
} // namespace eposp::can
