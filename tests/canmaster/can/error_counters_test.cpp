#include "eposp/can/error_counters.hpp"

#include <gtest/gtest.h>
#include <ostream>

namespace eposp::can {
namespace {

ErrorCounters after_transmit_errors(int count) {
    ErrorCounters counters;
    for (int i = 0; i < count; ++i) {
        counters.transmit_error(false);
    }
    return counters;
}

struct StateCase {
    int transmit_errors;
    ErrorState expected;
    friend void PrintTo(const StateCase& c, std::ostream* os) {
        *os << c.transmit_errors << " transmit errors";
    }
};

class ErrorCountersStateTest : public ::testing::TestWithParam<StateCase> {};

// ISO 11898-1:2015, 12.1.4: passive above 127, bus-off above 255; 8 per transmit error. The
// warning level from 96.
TEST_P(ErrorCountersStateTest, TransmitErrorsSetTheState) {
    const ErrorCounters counters = after_transmit_errors(GetParam().transmit_errors);
    EXPECT_EQ(counters.transmit(), 8U * static_cast<unsigned>(GetParam().transmit_errors));
    EXPECT_EQ(counters.state(), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    ErrorCounters, ErrorCountersStateTest,
    ::testing::Values(StateCase{0, ErrorState::Active}, StateCase{11, ErrorState::Active},
                      StateCase{12, ErrorState::Warning}, StateCase{15, ErrorState::Warning},
                      StateCase{16, ErrorState::Passive}, StateCase{31, ErrorState::Passive},
                      StateCase{32, ErrorState::BusOff}));

TEST(ErrorCounters, ReceiveErrorsFrom96AreTheWarningLevelAbove127Passive) {
    ErrorCounters counters;
    for (int i = 0; i < 95; ++i) {
        counters.receive_error();
    }
    EXPECT_EQ(counters.state(), ErrorState::Active);
    counters.receive_error();
    EXPECT_EQ(counters.state(), ErrorState::Warning);
    for (int i = 96; i < 127; ++i) {
        counters.receive_error();
    }
    EXPECT_EQ(counters.state(), ErrorState::Warning);
    counters.receive_error();
    EXPECT_EQ(counters.receive(), 128U);
    EXPECT_EQ(counters.state(), ErrorState::Passive);
}

TEST(ErrorCounters, SuccessCountsDownAndNeverBelowZero) {
    ErrorCounters counters = after_transmit_errors(1);
    counters.receive_error();
    for (int i = 0; i < 10; ++i) {
        counters.transmit_success();
        counters.receive_success();
    }
    EXPECT_EQ(counters.transmit(), 0U);
    EXPECT_EQ(counters.receive(), 0U);
}

TEST(ErrorCounters, ReceptionBringsAPassiveReceiveCounterBackTo119) {
    ErrorCounters counters;
    for (int i = 0; i < 130; ++i) {
        counters.receive_error();
    }
    counters.receive_success();
    EXPECT_EQ(counters.receive(), 119U);
    EXPECT_EQ(counters.state(), ErrorState::Warning); // error-active again, at the warning level
}

TEST(ErrorCounters, PassiveTransmitterIgnoresAckErrors) {
    ErrorCounters counters;
    for (int i = 0; i < 100; ++i) {
        counters.transmit_error(true);
    }
    EXPECT_EQ(counters.transmit(), 128U);
    EXPECT_EQ(counters.state(), ErrorState::Passive);
}

TEST(ErrorCounters, ForceSetsTheFirstValueOfAState) {
    ErrorCounters counters;
    counters.force(ErrorState::BusOff);
    EXPECT_EQ(counters.transmit(), 256U);
    counters.force(ErrorState::Passive);
    EXPECT_EQ(counters.transmit(), 128U);
    EXPECT_EQ(counters.state(), ErrorState::Passive);
    counters.reset();
    EXPECT_EQ(counters.state(), ErrorState::Active);
}

} // namespace
} // namespace eposp::can
