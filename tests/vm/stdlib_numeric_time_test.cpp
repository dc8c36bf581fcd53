// The numeric functions that are no opcode (IEC 61131-3 table 34/35) and the time and date
// arithmetic (table 36/37), through CallNative.

#include "stdlib_harness.hpp"

#include <cmath>
#include <limits>

namespace eposp::vm::test {
namespace {

struct RealCase {
    const char* function; ///< without the _REAL / _LREAL suffix
    std::vector<double> arguments;
    double expected;
};

void PrintTo(const RealCase& c, std::ostream* os) {
    *os << c.function;
}

class RealFunction : public ::testing::TestWithParam<RealCase> {};

TEST_P(RealFunction, ComputesItInLreal) {
    const auto& c = GetParam();
    StdlibCall call;
    std::vector<NativeArg> args;
    for (const auto a : c.arguments) {
        args.push_back(value(a));
    }
    ASSERT_EQ(call.call(std::string(c.function) + "_LREAL", args), RunState::Finished);
    if (std::isnan(c.expected)) {
        EXPECT_TRUE(std::isnan(call.result<double>()));
    } else {
        EXPECT_NEAR(call.result<double>(), c.expected, 1e-12);
    }
}

TEST_P(RealFunction, ComputesItInReal) {
    const auto& c = GetParam();
    StdlibCall call;
    std::vector<NativeArg> args;
    for (const auto a : c.arguments) {
        args.push_back(value(static_cast<float>(a)));
    }
    ASSERT_EQ(call.call(std::string(c.function) + "_REAL", args), RunState::Finished);
    if (std::isnan(c.expected)) {
        EXPECT_TRUE(std::isnan(call.result<float>()));
    } else {
        EXPECT_NEAR(call.result<float>(), c.expected, 1e-5);
    }
}

const double kPi = std::acos(-1.0);
const double kNaN = std::numeric_limits<double>::quiet_NaN();

INSTANTIATE_TEST_SUITE_P(
    Transcendental, RealFunction,
    ::testing::Values(RealCase{"LN", {std::exp(2.0)}, 2.0}, RealCase{"LN", {-1.0}, kNaN},
                      RealCase{"LOG", {1000.0}, 3.0}, RealCase{"EXP", {1.0}, std::exp(1.0)},
                      RealCase{"SIN", {kPi / 2}, 1.0}, RealCase{"COS", {kPi}, -1.0},
                      RealCase{"TAN", {kPi / 4}, 1.0}, RealCase{"ASIN", {1.0}, kPi / 2},
                      RealCase{"ASIN", {2.0}, kNaN}, RealCase{"ACOS", {0.0}, kPi / 2},
                      RealCase{"ATAN", {1.0}, kPi / 4}, RealCase{"ATAN2", {1.0, -1.0}, 3 * kPi / 4},
                      RealCase{"EXPT", {2.0, 10.0}, 1024.0}, RealCase{"EXPT", {-2.0, 3.0}, -8.0},
                      RealCase{"EXPT", {4.0, 0.5}, 2.0}, RealCase{"EXPT", {-8.0, 1.0 / 3}, kNaN}));

TEST(NumericFunctions, SqrtAndAbsAreOpcodesNotNatives) {
    NativeRegistry registry;
    stdlib::register_standard_library(registry);
    EXPECT_EQ(registry.find("SQRT_LREAL"), nullptr);
    EXPECT_EQ(registry.find("ABS_LREAL"), nullptr);
}

constexpr std::int64_t kMs = 1'000'000;
constexpr std::int64_t kS = 1'000 * kMs;
constexpr std::int64_t kH = 3'600 * kS;
constexpr std::int64_t kDay = 24 * kH;

struct TimeCase {
    const char* label;
    const char* function;
    std::vector<NativeArg> arguments;
    std::int64_t expected;
};

void PrintTo(const TimeCase& c, std::ostream* os) {
    *os << c.label;
}

class TimeFunction : public ::testing::TestWithParam<TimeCase> {};

TEST_P(TimeFunction, GivesTheIecResult) {
    const auto& c = GetParam();
    StdlibCall call;
    ASSERT_EQ(call.call(c.function, c.arguments), RunState::Finished)
        << call.harness.machine->describe_fault(0);
    EXPECT_EQ(call.result<std::int64_t>(), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Arithmetic, TimeFunction,
    ::testing::Values(
        TimeCase{"ADD_TOD_TIME", "ADD_TOD_TIME", {value(10 * kH), value(3 * kH)}, 13 * kH},
        TimeCase{"ADD_TOD_TIME_wraps_at_midnight",
                 "ADD_TOD_TIME",
                 {value(23 * kH), value(2 * kH)},
                 1 * kH},
        TimeCase{"ADD_TOD_TIME_negative", "ADD_TOD_TIME", {value(1 * kH), value(-2 * kH)}, 23 * kH},
        TimeCase{
            "ADD_TOD_TIME_days", "ADD_TOD_TIME", {value(1 * kH), value(3 * kDay + kS)}, kH + kS},
        TimeCase{"ADD_TOD_TIME_extreme_operands",
                 "ADD_TOD_TIME",
                 {value(std::numeric_limits<std::int64_t>::max()),
                  value(std::numeric_limits<std::int64_t>::max())},
                 2 * (std::numeric_limits<std::int64_t>::max() % kDay) - kDay},
        TimeCase{"SUB_TOD_TIME_wraps", "SUB_TOD_TIME", {value(1 * kH), value(2 * kH)}, 23 * kH},
        TimeCase{"DT_TO_DATE", "DT_TO_DATE", {value(5 * kDay + 7 * kH)}, 5 * kDay},
        TimeCase{"DT_TO_DATE_before_1970", "DT_TO_DATE", {value(-kH)}, -kDay},
        TimeCase{"DT_TO_TOD", "DT_TO_TOD", {value(5 * kDay + 7 * kH)}, 7 * kH},
        TimeCase{"DT_TO_TOD_before_1970", "DT_TO_TOD", {value(-kH)}, 23 * kH},
        TimeCase{"MUL_TIME", "MUL_TIME", {value(1500 * kMs), value(std::int64_t{3})}, 4500 * kMs},
        TimeCase{"MUL_TIME_LREAL", "MUL_TIME_LREAL", {value(kS), value(0.25)}, 250 * kMs},
        TimeCase{
            "MUL_TIME_LREAL_rounds", "MUL_TIME_LREAL", {value(std::int64_t{3}), value(0.5)}, 2},
        TimeCase{"MUL_TIME_LREAL_saturates",
                 "MUL_TIME_LREAL",
                 {value(kDay), value(1e300)},
                 std::numeric_limits<std::int64_t>::max()},
        TimeCase{"DIV_TIME", "DIV_TIME", {value(kS), value(std::int64_t{-4})}, -250 * kMs},
        TimeCase{"DIV_TIME_LREAL", "DIV_TIME_LREAL", {value(kS), value(8.0)}, 125 * kMs}));

TEST(TimeFunctions, DivisionByZeroStopsTheTask) {
    for (const auto* function : {"DIV_TIME", "DIV_TIME_LREAL"}) {
        StdlibCall call;
        const auto zero = std::string(function) == "DIV_TIME" ? value(std::int64_t{0}) : value(0.0);
        ASSERT_EQ(call.call(function, {value(kS), zero}), RunState::Faulted) << function;
        EXPECT_EQ(call.harness.machine->task(0).fault.native_reason,
                  "division by zero in DIV_TIME");
    }
}

TEST(TimeFunctions, PlainSumsAndDifferencesAreAdd64AndSub64) {
    // ADD_DT_TIME, SUB_DT_DT, CONCAT_DATE_TOD, ...: nanosecond counts, so one opcode each.
    Harness h;
    h.init(0, 19'753 * kDay);                                   // D#2024-01-31
    h.init(8, 12 * kH);                                         // TOD#12:00:00
    h.builder.emit(Opcode::Add64, self(16), self(0), self(8));  // CONCAT_DATE_TOD
    h.builder.emit(Opcode::Sub64, self(24), self(16), self(0)); // SUB_DT_DT
    h.builder.emit(Opcode::Ret);
    h.end_main();
    ASSERT_EQ(h.run(), RunState::Finished);
    EXPECT_EQ(h.get<std::int64_t>(16), 19'753 * kDay + 12 * kH);
    EXPECT_EQ(h.get<std::int64_t>(24), 12 * kH);
}

} // namespace
} // namespace eposp::vm::test
