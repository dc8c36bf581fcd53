// The CRC of maxon's serial protocols against the vectors of the EPOS2 communication guide and
// maxon's command library (docs/service-interface.md, "CRC").

#include "eposp/service/crc.hpp"
#include "random_frame.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::service {
namespace {

using test::bytes;
using test::Bytes;

// maxon's CalcFieldCRC as the guide prints it, word by word with a trailing zero word: the
// reference the Boost-based implementation must equal.
std::uint16_t guide_crc(const std::vector<std::uint16_t>& words) {
    std::uint16_t crc = 0;
    std::vector<std::uint16_t> with_zero = words;
    with_zero.push_back(0);
    for (const std::uint16_t word : with_zero) {
        for (std::uint16_t shifter = 0x8000; shifter != 0; shifter >>= 1) {
            const bool carry = (crc & 0x8000) != 0;
            crc = static_cast<std::uint16_t>(crc << 1 | ((word & shifter) != 0 ? 1 : 0));
            if (carry) {
                crc ^= 0x1021;
            }
        }
    }
    return crc;
}

TEST(ServiceCrc, V1ReadObjectRequestHasTheGuidesCrc) {
    EXPECT_EQ(v1_crc(Frame{0x10, bytes({0x41, 0x60, 0x00, 0x00})}), 0xC39A);
}

TEST(ServiceCrc, V1AnswerHasTheGuidesCrc) {
    EXPECT_EQ(v1_crc(Frame{0x00, bytes({0, 0, 0, 0, 0x37, 0x06, 0, 0})}), 0x4AE8);
}

TEST(ServiceCrc, V2FramesHaveTheGuidesCrc) {
    EXPECT_EQ(v2_crc(Frame{0x10, bytes({0x41, 0x60, 0x00, 0x01})}), 0xCF64);
    EXPECT_EQ(v2_crc(Frame{0x11, bytes({0x7A, 0x60, 0x00, 0x01, 0x90, 0, 0, 0})}), 0xD2E6);
    EXPECT_EQ(v2_crc(Frame{0x00, bytes({0, 0, 0, 0, 0x37, 0x06, 0, 0})}), 0xCA99);
}

TEST(ServiceCrc, EqualsTheGuidesWordWiseAlgorithmOnRandomFrames) {
    std::mt19937 random(20261129);
    for (int i = 0; i < 500; ++i) {
        const Frame frame = test::random_frame(random, 0, 255);
        const auto first = static_cast<std::uint16_t>(frame.words() << 8 | frame.opcode);
        std::vector<std::uint16_t> words{first};
        for (std::size_t at = 0; at < frame.data.size(); at += 2) {
            words.push_back(static_cast<std::uint16_t>(frame.data[at] | frame.data[at + 1] << 8));
        }
        ASSERT_EQ(frame_crc(first, frame.data), guide_crc(words)) << "frame " << i;
    }
}

TEST(ServiceCrc, RefusesFramesTheLinkCannotCarry) {
    EXPECT_THROW(v1_crc(Frame{0x10, {}}), std::invalid_argument);
    EXPECT_THROW(v1_crc(Frame{0x10, Bytes(2 * 257)}), std::invalid_argument);
    EXPECT_NO_THROW(v1_crc(Frame{0x10, Bytes(2 * 256)}));
    EXPECT_THROW(v2_crc(Frame{0x10, Bytes(2 * 256)}), std::invalid_argument);
    EXPECT_NO_THROW(v2_crc(Frame{0x10, {}}));
    EXPECT_THROW(v2_crc(Frame{0x10, Bytes(3)}), std::invalid_argument);
}

} // namespace
} // namespace eposp::service
