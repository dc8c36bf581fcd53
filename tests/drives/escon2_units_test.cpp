// ESCON2 FW spec 2.3: the user-defined units of 0x60A9 / 0x60AA (tables 10 - 13, 103, 105).
#include "eposp/drives/escon2/units.hpp"

#include <gtest/gtest.h>

namespace eposp::drives::escon2 {
namespace {

TEST(Escon2Units, DefaultVelocityUnitIsRevolutionsPerMinute) {
    const UserDefinedUnit unit = decode_unit(0x00B4'4700);
    EXPECT_EQ(unit.prefix, 0);
    EXPECT_EQ(unit.numerator, 0xB4);   // table 12: revolutions
    EXPECT_EQ(unit.denominator, 0x47); // table 11: minute
    EXPECT_DOUBLE_EQ(velocity_unit_in_rpm(0x00B4'4700), 1.0);
}

TEST(Escon2Units, MilliPrefixMakesAThousandthOfARevolutionPerMinute) {
    EXPECT_EQ(decode_unit(0xFDB4'4700).prefix, -3); // table 13: 0xFD milli
    EXPECT_DOUBLE_EQ(velocity_unit_in_rpm(0xFDB4'4700), 1e-3);
}

TEST(Escon2Units, AccelerationUnitIsRpmPerSecond) {
    const UserDefinedUnit unit = decode_unit(0x00C0'0300);
    EXPECT_EQ(unit.numerator, 0xC0);   // table 12: rpm
    EXPECT_EQ(unit.denominator, 0x03); // table 11: second
}

} // namespace
} // namespace eposp::drives::escon2
