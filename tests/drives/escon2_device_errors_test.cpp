// ESCON2 FW spec 7.1: table 110 transcribed row by row (code, error register, name, fault
// reaction code) with the recovery of each section 7.1.x, against the drive's data; and the
// error handling on the dictionary (0x1001, 0x1003, 0x603F).
#include "eposp/drives/escon2/device_errors.hpp"
#include "eposp/drives/escon2/error_handling.hpp"
#include "eposp/drives/escon2/escon2_dictionary.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace eposp::drives::escon2 {
namespace {

constexpr auto kFaultReset = ErrorRecovery::FaultReset;
constexpr auto kResetDevice = ErrorRecovery::ResetDevice;
constexpr auto kAutoClear = ErrorRecovery::AutoClear;
constexpr auto kClearWarning = ErrorRecovery::ClearWarning;

struct Row {
    std::uint16_t code;
    std::uint8_t error_register;
    const char* name;
    char reaction; ///< f, d, w
    ErrorRecovery recovery;
};

// clang-format off
const std::vector<Row> kTable110 = {
    {0x1000, 0b0000'0001, "Generic error", 'd', kFaultReset},
    {0x1080, 0b0000'0001, "Generic initialisation error", 'd', kResetDevice},
    {0x2310, 0b0000'0011, "Overcurrent error", 'd', kFaultReset},
    {0x2320, 0b0000'0011, "Power stage protection error", 'd', kFaultReset},
    {0x2380, 0b0000'0011, "Power stage protection error", 'd', kFaultReset},
    {0x3210, 0b0000'0101, "Overvoltage error", 'd', kFaultReset},
    {0x3220, 0b0000'0101, "Undervoltage error", 'd', kFaultReset},
    {0x4382, 0b0000'1001, "Thermal power stage overload error", 'd', kFaultReset},
    {0x4383, 0b0000'1001, "Thermal power stage overload warning", 'w', kAutoClear},
    {0x4384, 0b0000'1001, "Thermal logic section overload error", 'd', kFaultReset},
    {0x5480, 0b0000'0001, "Hardware error", 'd', kResetDevice},
    {0x5481, 0b0000'0001, "Hardware defect loading parameter error", 'd', kResetDevice},
    {0x5482, 0b0000'0001, "Hardware configuration error", 'd', kResetDevice},
    {0x5483, 0b0000'0001, "Hardware configuration error", 'd', kResetDevice},
    {0x6180, 0b0000'0001, "Internal software error", 'd', kResetDevice},
    {0x6181, 0b0000'0001, "Internal software error", 'd', kFaultReset},
    {0x6380, 0b0000'0001, "Loading parameter failed error", 'd', kFaultReset},
    {0x6381, 0b0000'0001, "Loading parameter failed error", 'd', kResetDevice},
    {0x6382, 0b0000'0001, "Loading parameter failed error", 'd', kResetDevice},
    {0x6388, 0b0000'0001, "Torque constant parameter error", 'd', kFaultReset},
    {0x7280, 0b0000'0001, "Current offset adjustment warning", 'w', kAutoClear},
    {0x7380, 0b0010'0001, "Main sensor breach error", 'd', kFaultReset},
    {0x7388, 0b0010'0001, "Hall sensor signal error", 'd', kFaultReset},
    {0x738A, 0b0010'0001, "Hall angle detection error", 'd', kFaultReset},
    {0x7390, 0b0010'0001, "Missing main sensor error", 'd', kFaultReset},
    {0x7391, 0b0010'0001, "Missing commutation sensor error", 'd', kFaultReset},
    {0x7392, 0b0010'0001, "Main sensor direction error", 'd', kFaultReset},
    {0x8A80, 0b0010'0001, "Negative limit switch error", 'f', kFaultReset},
    {0x8A81, 0b0010'0001, "Positive limit switch error", 'f', kFaultReset},
    {0x8A89, 0b0000'0001, "Digital input 1 PWM frequency warning", 'w', kAutoClear},
    {0x8A8A, 0b0000'0001, "Digital input 1 PWM duty cycle warning", 'w', kAutoClear},
    {0x8A8C, 0b0000'0001, "Digital input 1 PWM error", 'd', kFaultReset},
    {0x8A8D, 0b0000'0001, "Digital input 2 PWM frequency warning", 'w', kAutoClear},
    {0x8A8E, 0b0000'0001, "Digital input 2 PWM duty cycle warning", 'w', kAutoClear},
    {0x8A90, 0b0000'0001, "Digital input 2 PWM error", 'd', kFaultReset},
    {0xFF01, 0b0000'0001, "System overloaded warning", 'w', kClearWarning},
    {0xFF02, 0b0000'0001, "Watchdog error", 'd', kFaultReset},
    {0xFF03, 0b0000'0001, "Watchdog error", 'd', kFaultReset},
    {0xFF06, 0b0000'0001, "System peak overloaded error", 'd', kFaultReset},
    {0xFF07, 0b0000'0001, "System peak overloaded error", 'd', kFaultReset},
    {0xFF0D, 0b0000'0001, "Mode of operation not supported error", 'd', kFaultReset},
    {0xFF11, 0b0010'0001, "Regulation tuning identification error", 'd', kFaultReset},
    {0xFF12, 0b0010'0001, "Regulation tuning current error", 'd', kFaultReset},
    {0xFF13, 0b0010'0001, "Regulation tuning identification current error", 'd', kFaultReset},
    {0xFF14, 0b0010'0001, "Regulation tuning unrealistic result error", 'd', kFaultReset},
    {0xFF15, 0b0010'0001, "Regulation tuning identification error", 'd', kFaultReset},
    {0xFF16, 0b0010'0001, "Regulation tuning identification error", 'd', kFaultReset},
    {0xFF17, 0b0010'0001, "Regulation tuning identification error", 'd', kFaultReset},
    {0xFF19, 0b0010'0001, "Regulation tuning identification error", 'd', kFaultReset},
    {0xFF20, 0b0010'0001, "Regulation tuning standstill error", 'd', kFaultReset},
    {0xFF21, 0b0010'0001, "Regulation tuning torque constant error", 'd', kFaultReset},
    {0xFF22, 0b0010'0001, "Regulation tuning max system speed error", 'd', kFaultReset},
    {0xFF23, 0b0010'0001, "Regulation tuning motor connection error", 'd', kFaultReset},
    {0xFF24, 0b0010'0001, "Regulation tuning sensor signal error", 'd', kFaultReset},
};
// clang-format on

TEST(Escon2DeviceErrors, AreTable110RowByRow) {
    const auto errors = device_errors();
    ASSERT_EQ(errors.size(), kTable110.size());
    for (std::size_t i = 0; i < kTable110.size(); ++i) {
        const Row& row = kTable110[i];
        SCOPED_TRACE(fmt::format("0x{:04X} {}", row.code, row.name));
        EXPECT_EQ(errors[i].code, row.code);
        EXPECT_EQ(errors[i].error_register, row.error_register);
        EXPECT_EQ(errors[i].name, row.name);
        EXPECT_EQ(static_cast<char>(errors[i].reaction), row.reaction);
        EXPECT_EQ(errors[i].recovery, row.recovery);
        EXPECT_EQ(&device_error(row.code), &errors[i]);
    }
}

TEST(Escon2DeviceErrors, ACodeTheTableDoesNotListIsRefused) {
    EXPECT_THROW(device_error(0x0000), std::invalid_argument);
    EXPECT_THROW(device_error(0x8611), std::invalid_argument) << "an EPOS2 code";
}

class Escon2ErrorHandling : public ::testing::Test {
protected:
    std::uint32_t history(std::uint8_t sub) const { return od.get_as<std::uint32_t>(0x1003, sub); }
    std::uint8_t error_register() const { return od.get_as<std::uint8_t>(0x1001, 0); }
    std::uint16_t error_code() const { return od.get_as<std::uint16_t>(0x603F, 0); }

    Escon2Dictionary dictionary{Escon2DictionaryConfig{}};
    canopen::ObjectDictionary& od = dictionary.objects();
    ErrorHandling errors{od};
};

// 6.2.3.2: newest at sub 1; a warning carries bit 31; an active entry is not entered twice.
TEST_F(Escon2ErrorHandling, HistoryHoldsErrorsAndMarksWarnings) {
    EXPECT_TRUE(errors.raise(0x4383));
    EXPECT_TRUE(errors.raise(0x3220));
    EXPECT_FALSE(errors.raise(0x3220));
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1003, 0), 2);
    EXPECT_EQ(history(1), 0x0000'3220u);
    EXPECT_EQ(history(2), 0x8000'4383u);
}

// Table 35: the bits of every active entry; the warning's stay while it is active.
TEST_F(Escon2ErrorHandling, ErrorRegisterIsTheBitsOfTheActiveEntries) {
    errors.raise(0x4383); // 0000 1001b
    EXPECT_EQ(error_register(), 0b0000'1001);
    errors.raise(0x8A80); // 0010 0001b
    EXPECT_EQ(error_register(), 0b0010'1001);
    errors.fault_reset();
    EXPECT_EQ(error_register(), 0b0000'1001);
    errors.clear_warning(0x4383);
    EXPECT_EQ(error_register(), 0);
}

// 6.2.58: a non-erasable error before an erasable one before a warning; a warning only while
// active.
TEST_F(Escon2ErrorHandling, ErrorCodeShowsTheWeightiestActiveEntry) {
    errors.raise(0x8A89);
    EXPECT_EQ(error_code(), 0x8A89);
    errors.raise(0x5480);
    errors.raise(0x2310);
    EXPECT_EQ(error_code(), 0x5480) << "reset device beats a fault reset";
    errors.fault_reset();
    EXPECT_EQ(error_code(), 0x5480);
    EXPECT_TRUE(errors.needs_device_reset());
    errors.reset();
    EXPECT_EQ(error_code(), 0);
    errors.raise(0x8A8A);
    errors.clear_warning(0x8A8A);
    EXPECT_EQ(error_code(), 0);
}

// 7.1.36: only the system overload warning is reset with the controlword; the others clear
// with their cause.
TEST_F(Escon2ErrorHandling, ClearWarningResetsOnlyTheWarningsItApplies) {
    errors.raise(0xFF01);
    errors.raise(0x4383);
    errors.clear_warnings();
    EXPECT_FALSE(errors.active(0xFF01));
    EXPECT_TRUE(errors.active(0x4383));
    EXPECT_TRUE(errors.warning_active());
}

} // namespace
} // namespace eposp::drives::escon2
