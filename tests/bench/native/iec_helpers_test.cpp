#include "eposp/bench/native/iec_arith.hpp"
#include "eposp/bench/native/iec_string.hpp"
#include "eposp/bench/native/standard_fbs.hpp"

#include <chrono>
#include <gtest/gtest.h>
#include <string>

namespace eposp::bench::native {
namespace {

using std::chrono::milliseconds;

TEST(IecArithmetic, DintOverflowWrapsAroundInTwosComplement) {
    EXPECT_EQ(wrap_mul(std::int32_t{65536}, std::int32_t{65537}), 65536);
    EXPECT_EQ(wrap_add(std::int32_t{INT32_MAX}, std::int32_t{1}), INT32_MIN);
    EXPECT_EQ(wrap_neg(std::int32_t{INT32_MIN}), INT32_MIN);
}

TEST(IecArithmetic, LrealToDintRoundsToNearestTiesToEven) {
    EXPECT_EQ(lreal_to_dint(736486.794), 736487);
    EXPECT_EQ(lreal_to_dint(2.5), 2);
    EXPECT_EQ(lreal_to_dint(-1.5), -2);
}

TEST(IecString, ConcatTruncatesAtTheDefaultCapacityOf80) {
    const String long_text{std::string(70, 'a')};
    const String joined = concat(long_text, std::string(20, 'b'));
    EXPECT_EQ(len(joined), 80);
    EXPECT_EQ(joined.view().substr(68), "aabbbbbbbbbb");
}

TEST(IecString, PositionsAreOneBased) {
    const String s{"ID=12;POS=480"};
    EXPECT_EQ(find(s, ";"), 6);
    EXPECT_EQ(find(s, "x"), 0);
    EXPECT_EQ(mid(s, 7, 7).view(), "POS=480");
    EXPECT_EQ(mid(s, 20, 11).view(), "480");
    EXPECT_EQ(left(s, 3).view(), "ID=");
    EXPECT_EQ(left(s, 40).view(), s.view());
}

TEST(IecString, OutOfRangeArgumentsGiveTheEmptyString) {
    const String s{"abc"};
    EXPECT_EQ(len(mid(s, 1, 0)), 0);
    EXPECT_EQ(len(mid(s, 1, 4)), 0);
    EXPECT_EQ(len(mid(s, -1, 1)), 0);
    EXPECT_EQ(len(left(s, -2)), 0);
}

TEST(IecString, IntToStringGivesTheDecimalLiteral) {
    EXPECT_EQ(int_to_string(0).view(), "0");
    EXPECT_EQ(int_to_string(-32768).view(), "-32768");
    EXPECT_EQ(int_to_string(1041).view(), "1041");
}

TEST(StandardFbs, TonQRisesWhenEtReachesPtAndResetsWithIn) {
    Ton ton;
    const core::TimePoint t0{};
    ton(true, milliseconds(2), t0);
    EXPECT_FALSE(ton.q);
    ton(true, milliseconds(2), t0 + milliseconds(1));
    EXPECT_FALSE(ton.q);
    EXPECT_EQ(ton.et, milliseconds(1));
    ton(true, milliseconds(2), t0 + milliseconds(2));
    EXPECT_TRUE(ton.q);
    ton(true, milliseconds(2), t0 + milliseconds(9));
    EXPECT_EQ(ton.et, milliseconds(2));
    ton(false, milliseconds(2), t0 + milliseconds(10));
    EXPECT_FALSE(ton.q);
    EXPECT_EQ(ton.et, milliseconds(0));
}

TEST(StandardFbs, CtuCountsRisingEdgesOnlyAndResetHasPriority) {
    Ctu ctu;
    ctu(true, false, 2);
    ctu(true, false, 2);
    EXPECT_EQ(ctu.cv, 1);
    ctu(false, false, 2);
    ctu(true, false, 2);
    EXPECT_EQ(ctu.cv, 2);
    EXPECT_TRUE(ctu.q);
    ctu(false, true, 2);
    EXPECT_EQ(ctu.cv, 0);
    EXPECT_FALSE(ctu.q);
}

TEST(StandardFbs, RTrigPulsesForOneCallAndSrIsSetDominant) {
    RTrig edge;
    edge(true);
    EXPECT_TRUE(edge.q);
    edge(true);
    EXPECT_FALSE(edge.q);

    Sr latch;
    latch(true, true);
    EXPECT_TRUE(latch.q1);
    latch(false, false);
    EXPECT_TRUE(latch.q1);
    latch(false, true);
    EXPECT_FALSE(latch.q1);
}

} // namespace
} // namespace eposp::bench::native
