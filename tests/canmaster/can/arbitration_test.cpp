#include "eposp/can/arbitration.hpp"

#include <gtest/gtest.h>

namespace eposp::can {
namespace {

TEST(Arbitration, FieldIsTheWireBitsOfIdentifierRtrSrrAndIde) {
    // Base identifier in the top 11 bits, then RTR (standard) or SRR, then IDE.
    EXPECT_EQ(arbitration_field(Frame::data_frame(0x7FF, {})), 0x7FFU << 21);
    EXPECT_EQ(arbitration_field(Frame::remote_frame(0x000, 0)), 1U << 20);
    EXPECT_EQ(arbitration_field(Frame::data_frame(0x000, {}, true)), 3U << 19);
    EXPECT_EQ(arbitration_field(Frame::remote_frame(0x1FFFFFFF, 0, true)), 0xFFFFFFFFU);
}

TEST(Arbitration, DominantBitWinsAtTheFirstDifference) {
    EXPECT_TRUE(wins_arbitration(Frame::data_frame(0x100, {}), Frame::data_frame(0x101, {})));
    EXPECT_TRUE(wins_arbitration(Frame::data_frame(0x100, {}), Frame::remote_frame(0x100, 0)));
    EXPECT_TRUE(
        wins_arbitration(Frame::remote_frame(0x100, 0), Frame::data_frame(0x100 << 18, {}, true)));
    EXPECT_TRUE(
        wins_arbitration(Frame::data_frame(0x3FFFF, {}, true), Frame::data_frame(0x001, {})));
    EXPECT_FALSE(wins_arbitration(Frame::data_frame(0x100, {}), Frame::data_frame(0x100, {1})));
}

} // namespace
} // namespace eposp::can
