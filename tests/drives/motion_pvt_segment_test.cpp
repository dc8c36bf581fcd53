// The cubic of a PVT segment (EPOS2 FW spec 5.5.1) meets both reference points with their
// velocities, and its velocity and acceleration are the derivatives of its position.
#include "eposp/drives/motion/pvt_segment.hpp"

#include <gtest/gtest.h>

namespace eposp::drives::motion {
namespace {

TEST(PvtSegment, StartsAndEndsAtItsReferencePointsWithTheirVelocities) {
    const PvtSegment segment(100, 2000, 900, -500, 0.25);
    EXPECT_DOUBLE_EQ(segment.at(0).position, 100);
    EXPECT_DOUBLE_EQ(segment.at(0).velocity, 2000);
    EXPECT_NEAR(segment.at(0.25).position, 900, 1e-9);
    EXPECT_NEAR(segment.at(0.25).velocity, -500, 1e-9);
    EXPECT_DOUBLE_EQ(segment.duration(), 0.25);
}

TEST(PvtSegment, VelocityAndAccelerationAreTheDerivativesOfPosition) {
    const PvtSegment segment(0, 100, 1000, 300, 0.5);
    const double h = 1e-6;
    for (const double t : {0.05, 0.2, 0.41}) {
        EXPECT_NEAR(segment.at(t).velocity,
                    (segment.at(t + h).position - segment.at(t - h).position) / (2 * h), 1e-3);
        EXPECT_NEAR(segment.at(t).acceleration,
                    (segment.at(t + h).velocity - segment.at(t - h).velocity) / (2 * h), 1e-2);
    }
}

TEST(PvtSegment, FromRestToRestItIsSymmetricAboutItsMiddle) {
    const PvtSegment segment(0, 0, 1000, 0, 0.1);
    EXPECT_NEAR(segment.at(0.05).position, 500, 1e-9);
    EXPECT_NEAR(segment.at(0.05).velocity, 1.5 * 1000 / 0.1, 1e-6); // peak of the cubic
}

} // namespace
} // namespace eposp::drives::motion
