// The ESCON2's digital inputs (ESCON2 FW spec 4.1, 6.2.26 - 6.2.30, 6.2.77): filter times,
// polarity, the functionality table and which input may carry what.
#include "eposp/drives/escon2/io/digital_inputs.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

constexpr std::uint32_t bit(InputFunction function) {
    return 1U << static_cast<unsigned>(function);
}

DigitalInputs with_functions(std::array<InputFunction, kDigitalInputCount> functions,
                             std::uint16_t polarity = 0) {
    DigitalInputs inputs;
    EXPECT_FALSE(inputs.configure({.functions = functions, .polarity = polarity}));
    return inputs;
}

// 4.1.1: "The input level needs to stay steady for longer than the filter time": 1 ms.
TEST(Escon2DigitalInputs, RegularInputChangesAfterOneMillisecondNotBefore) {
    DigitalInputs inputs; // default: inputs 1 - 4 general purpose A - D (6.2.27)
    inputs.set_level(1, true, 0.010);
    EXPECT_EQ(inputs.functionality(0.0105), 0U);
    EXPECT_EQ(inputs.functionality(0.011), 0U);
    EXPECT_EQ(inputs.functionality(0.01101), bit(InputFunction::GeneralPurposeA));
    EXPECT_EQ(inputs.logic_state(0.01101), 0x01);
    inputs.set_level(1, false, 0.020);
    EXPECT_EQ(inputs.logic_state(0.0209), 0x01);
    EXPECT_EQ(inputs.logic_state(0.02101), 0x00);
}

// 4.1.1: 500 µs for the high-speed inputs.
TEST(Escon2DigitalInputs, HighSpeedInputChangesAfterFiveHundredMicroseconds) {
    DigitalInputs inputs =
        with_functions({InputFunction::None, InputFunction::None, InputFunction::None,
                        InputFunction::None, InputFunction::GeneralPurposeE, InputFunction::None,
                        InputFunction::None, InputFunction::None});
    inputs.set_level(5, true, 0);
    EXPECT_FALSE(inputs.active(InputFunction::GeneralPurposeE, 0.0005));
    EXPECT_TRUE(inputs.active(InputFunction::GeneralPurposeE, 0.00051));
    EXPECT_EQ(inputs.logic_state(0.00051), 0x10);
}

// A spike shorter than the filter time is never seen, however long one waits after it.
TEST(Escon2DigitalInputs, SpikeShorterThanTheFilterIsIgnored) {
    DigitalInputs inputs;
    inputs.set_level(2, true, 0);
    inputs.set_level(2, false, 0.0009);
    EXPECT_EQ(inputs.logic_state(0.0009), 0);
    EXPECT_EQ(inputs.logic_state(1), 0);
}

// 6.2.26: the logic state is the pin before the polarity; a set polarity bit makes a low pin
// the active one in 0x3143.
TEST(Escon2DigitalInputs, PolarityInvertsTheFunctionalityNotTheLogicState) {
    DigitalInputs inputs =
        with_functions({InputFunction::GeneralPurposeA, InputFunction::QuickStop,
                        InputFunction::None, InputFunction::None, InputFunction::None,
                        InputFunction::None, InputFunction::None, InputFunction::None},
                       0x0002);
    EXPECT_EQ(inputs.functionality(1), bit(InputFunction::QuickStop));
    EXPECT_EQ(inputs.logic_state(1), 0);
    inputs.set_level(2, true, 1);
    EXPECT_EQ(inputs.functionality(2), 0U);
    EXPECT_EQ(inputs.logic_state(2), 0x02);
}

// Table 59, one functionality per row: the input carrying it sets its bit in 0x3143; 0x60FD
// shows only the CiA ones (limit switches, general purpose A - H).
struct FunctionRow {
    InputFunction function;
    bool in_cia_object;
};
class Escon2DigitalInputFunction : public testing::TestWithParam<FunctionRow> {};

TEST_P(Escon2DigitalInputFunction, ActiveInputSetsItsBit) {
    const FunctionRow row = GetParam();
    DigitalInputs inputs = with_functions(
        {InputFunction::None, InputFunction::None, InputFunction::None, row.function,
         InputFunction::None, InputFunction::None, InputFunction::None, InputFunction::None});
    EXPECT_EQ(inputs.input_of(row.function), 4U);
    inputs.set_level(4, true, 0);
    EXPECT_EQ(inputs.functionality(1), bit(row.function));
    EXPECT_EQ(inputs.cia_inputs(1), row.in_cia_object ? bit(row.function) : 0U);
    EXPECT_TRUE(inputs.active(row.function, 1));
}

INSTANTIATE_TEST_SUITE_P(Table59, Escon2DigitalInputFunction,
                         testing::Values(FunctionRow{InputFunction::NegativeLimitSwitch, true},
                                         FunctionRow{InputFunction::PositiveLimitSwitch, true},
                                         FunctionRow{InputFunction::VelocitySetValueSwitch0, false},
                                         FunctionRow{InputFunction::VelocitySetValueSwitch1, false},
                                         FunctionRow{InputFunction::CurrentSetValueSwitch0, false},
                                         FunctionRow{InputFunction::CurrentSetValueSwitch1, false},
                                         FunctionRow{InputFunction::GeneralPurposeA, true},
                                         FunctionRow{InputFunction::GeneralPurposeB, true},
                                         FunctionRow{InputFunction::GeneralPurposeC, true},
                                         FunctionRow{InputFunction::GeneralPurposeD, true},
                                         FunctionRow{InputFunction::GeneralPurposeE, true},
                                         FunctionRow{InputFunction::GeneralPurposeF, true},
                                         FunctionRow{InputFunction::GeneralPurposeG, true},
                                         FunctionRow{InputFunction::GeneralPurposeH, true},
                                         FunctionRow{InputFunction::DriveEnable, false},
                                         FunctionRow{InputFunction::QuickStop, false},
                                         FunctionRow{InputFunction::Direction, false}));

// Table 59 [a]: a PWM functionality only on digital input 1 or 2; there its pin reads 0 in the
// logic state, it has no bit and the polarity does not act.
TEST(Escon2DigitalInputs, PwmFunctionalityOnlyOnInputOneOrTwo) {
    DigitalInputConfiguration config;
    config.functions[2] = InputFunction::PwmVelocitySetValue;
    DigitalInputs inputs;
    const std::optional<std::string> error = inputs.configure(config);
    ASSERT_TRUE(error);
    EXPECT_NE(error->find("input 3"), std::string::npos) << *error;
    EXPECT_EQ(inputs.configuration().functions[2], InputFunction::GeneralPurposeC); // kept

    config.functions[2] = InputFunction::GeneralPurposeC;
    config.functions[1] = InputFunction::PwmCurrentSetValue;
    config.polarity = 0x0002;
    ASSERT_FALSE(inputs.configure(config));
    inputs.set_level(2, true, 0);
    EXPECT_EQ(inputs.logic_state(1), 0);
    EXPECT_EQ(inputs.functionality(1), 0U);
    EXPECT_EQ(inputs.input_of(InputFunction::PwmCurrentSetValue), 2U);
}

// 6.2.27.1: "Each function can only be mapped once".
TEST(Escon2DigitalInputs, AFunctionMappedTwiceIsRefused) {
    DigitalInputConfiguration config;
    config.functions[0] = InputFunction::DriveEnable;
    config.functions[6] = InputFunction::DriveEnable;
    const std::optional<std::string> error = configuration_error(config);
    ASSERT_TRUE(error);
    EXPECT_NE(error->find("mapped once"), std::string::npos) << *error;
    config.functions[6] = InputFunction::None;
    config.functions[7] = InputFunction::None; // None may appear on many inputs
    EXPECT_FALSE(configuration_error(config));
}

// 6.2.27: with sensor 2 configured the high-speed inputs are disabled.
TEST(Escon2DigitalInputs, SensorTwoDisablesTheHighSpeedInputs) {
    DigitalInputConfiguration config;
    config.functions[4] = InputFunction::PositiveLimitSwitch;
    config.sensor2_configured = true;
    DigitalInputs inputs;
    ASSERT_FALSE(inputs.configure(config));
    inputs.set_level(5, true, 0);
    EXPECT_EQ(inputs.logic_state(1), 0);
    EXPECT_FALSE(inputs.input_of(InputFunction::PositiveLimitSwitch));
    EXPECT_FALSE(inputs.limit_switch_error(1));
}

// Table 61: switch 1 and switch 0 select set value 2 · s1 + s0; an unmapped switch reads 0;
// nothing is selected while neither is mapped.
TEST(Escon2DigitalInputs, SetValueSwitchesSelectTheFixedSetValues) {
    DigitalInputs inputs = with_functions(
        {InputFunction::VelocitySetValueSwitch0, InputFunction::VelocitySetValueSwitch1,
         InputFunction::CurrentSetValueSwitch1, InputFunction::None, InputFunction::None,
         InputFunction::None, InputFunction::None, InputFunction::None});
    const struct {
        bool s1, s0;
        unsigned selected;
    } rows[] = {{false, false, 0}, {false, true, 1}, {true, false, 2}, {true, true, 3}};
    double now = 0;
    for (const auto& row : rows) {
        inputs.set_level(1, row.s0, now);
        inputs.set_level(2, row.s1, now);
        now += 0.002;
        EXPECT_EQ(inputs.selected_set_value(SetValueSwitch::Velocity, now), row.selected);
    }
    inputs.set_level(3, true, now); // current switch 0 unmapped, switch 1 active: value 2
    EXPECT_EQ(inputs.selected_set_value(SetValueSwitch::Current, now + 0.002), 2U);
    EXPECT_FALSE(DigitalInputs().selected_set_value(SetValueSwitch::Velocity, now));
}

// Table 59 [d].
TEST(Escon2DigitalInputs, DirectionInvertsAPositiveSetValueWhileInactive) {
    EXPECT_EQ(apply_direction(1000, true), 1000);
    EXPECT_EQ(apply_direction(1000, false), -1000);
    EXPECT_EQ(apply_direction(-1000, true), 0);
    EXPECT_EQ(apply_direction(-1000, false), 0);
    EXPECT_EQ(apply_direction(-1000, std::nullopt), -1000); // Direction not mapped
}

// 7.1.28 / 7.1.29.
TEST(Escon2DigitalInputs, ActiveLimitSwitchRaisesItsError) {
    DigitalInputs inputs =
        with_functions({InputFunction::NegativeLimitSwitch, InputFunction::PositiveLimitSwitch,
                        InputFunction::None, InputFunction::None, InputFunction::None,
                        InputFunction::None, InputFunction::None, InputFunction::None});
    EXPECT_FALSE(inputs.limit_switch_error(1));
    inputs.set_level(2, true, 1);
    EXPECT_EQ(inputs.limit_switch_error(1.002), DeviceErrorCode::PositiveLimitSwitch);
    inputs.set_level(1, true, 1);
    EXPECT_EQ(inputs.limit_switch_error(1.002), DeviceErrorCode::NegativeLimitSwitch);
    EXPECT_EQ(static_cast<unsigned>(DeviceErrorCode::NegativeLimitSwitch), 0x8A80U);
}

// Table 59 [b], [c] and the reserved codes.
TEST(Escon2DigitalInputs, FunctionalitiesActInTheirModeAndReservedCodesAreNone) {
    EXPECT_TRUE(acts_in(InputFunction::PwmVelocitySetValue, IoMode::Velocity));
    EXPECT_FALSE(acts_in(InputFunction::PwmVelocitySetValue, IoMode::Current));
    EXPECT_FALSE(acts_in(InputFunction::CurrentSetValueSwitch0, IoMode::Velocity));
    EXPECT_TRUE(acts_in(InputFunction::Direction, IoMode::Current));
    EXPECT_TRUE(acts_in(InputFunction::Direction, IoMode::Velocity));
    EXPECT_EQ(input_function_from_code(37), InputFunction::PwmCurrentSetValueOffset);
    EXPECT_EQ(input_function_from_code(255), InputFunction::None);
    for (const int reserved : {2, 11, 24, 26, 30, 34, 35, 38, 254}) {
        EXPECT_FALSE(input_function_from_code(static_cast<std::uint8_t>(reserved))) << reserved;
    }
}

TEST(Escon2DigitalInputs, UnknownInputIsAnError) {
    DigitalInputs inputs;
    EXPECT_THROW(inputs.set_level(0, true, 0), std::out_of_range);
    EXPECT_THROW(inputs.set_level(9, true, 0), std::out_of_range);
}

} // namespace
} // namespace eposp::drives::escon2
