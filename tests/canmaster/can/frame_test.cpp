#include "eposp/can/frame.hpp"

#include <gtest/gtest.h>

namespace eposp::can {
namespace {

TEST(Frame, DataFrameCarriesItsBytes) {
    const Frame frame = Frame::data_frame(0x181, {0x11, 0x22, 0x33});
    EXPECT_EQ(frame.dlc, 3);
    EXPECT_FALSE(frame.remote);
    ASSERT_EQ(frame.payload().size(), 3U);
    EXPECT_EQ(frame.payload()[2], 0x33);
    EXPECT_TRUE(frame.valid());
}

TEST(Frame, RemoteFrameHasDlcButNoPayload) {
    const Frame frame = Frame::remote_frame(0x701, 1);
    EXPECT_TRUE(frame.remote);
    EXPECT_EQ(frame.dlc, 1);
    EXPECT_TRUE(frame.payload().empty());
}

TEST(Frame, IdentifierMustFitItsFormat) {
    EXPECT_TRUE(Frame::data_frame(0x7FF, {}).valid());
    EXPECT_FALSE(Frame::data_frame(0x800, {}).valid());
    EXPECT_TRUE(Frame::data_frame(0x1FFFFFFF, {}, true).valid());
    EXPECT_FALSE(Frame::data_frame(0x20000000, {}, true).valid());
}

TEST(Frame, DlcAboveEightIsInvalid) {
    Frame frame = Frame::data_frame(0x100, {});
    frame.dlc = 9;
    EXPECT_FALSE(frame.valid());
}

TEST(Frame, ErrorFramesCannotBeSent) {
    Frame frame;
    frame.error = true;
    EXPECT_FALSE(frame.valid());
}

TEST(Frame, EqualityIgnoresBytesBeyondTheDlc) {
    Frame a = Frame::data_frame(0x100, {1, 2});
    Frame b = a;
    b.data[5] = 0xAA;
    EXPECT_EQ(a, b);
    b.data[1] = 0x03;
    EXPECT_NE(a, b);
}

} // namespace
} // namespace eposp::can
