#include "eposp/core/time.hpp"

#include <gtest/gtest.h>

namespace eposp::core {
namespace {

using namespace std::chrono_literals;

TEST(ParseDuration, AcceptsTheUnitsUsersType) {
    EXPECT_EQ(parse_duration("10s"), Duration{10s});
    EXPECT_EQ(parse_duration("250ms"), Duration{250ms});
    EXPECT_EQ(parse_duration("1.5s"), Duration{1500ms});
    EXPECT_EQ(parse_duration("100us"), Duration{100us});
    EXPECT_EQ(parse_duration("500ns"), Duration{500ns});
    EXPECT_EQ(parse_duration("2m"), Duration{120s});
    EXPECT_EQ(parse_duration("1h"), Duration{3600s});
    EXPECT_EQ(parse_duration("3"), Duration{3s});
}

TEST(ParseDuration, RejectsGarbageAndNegativeValues) {
    for (const char* text : {"", "s", "-1s", "10 s", "10sec", "abc", "1e30h", "nan"}) {
        EXPECT_EQ(parse_duration(text), std::nullopt) << text;
    }
}

TEST(FormatDuration, UsesTheLargestExactUnit) {
    EXPECT_EQ(format_duration(2s), "2s");
    EXPECT_EQ(format_duration(1500ms), "1500ms");
    EXPECT_EQ(format_duration(40us), "40us");
    EXPECT_EQ(format_duration(Duration{333'333}), "333333ns");
    EXPECT_EQ(format_duration(Duration::zero()), "0s");
}

TEST(FormatSecondsMicros, PadsMicroseconds) {
    EXPECT_EQ(format_seconds_micros(TimePoint{1s + 2500us}), "1.002500");
}

} // namespace
} // namespace eposp::core
