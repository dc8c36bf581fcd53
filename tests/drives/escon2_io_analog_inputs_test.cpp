// The ESCON2's analog inputs (ESCON2 FW spec 4.3, 6.2.36 - 6.2.40, 6.2.48 - 6.2.51): adjustment,
// raw value, general purpose values, the set value scaling and the configuration rules.
#include "eposp/drives/escon2/io/analog_inputs.hpp"
#include "eposp/drives/escon2/io/two_point_scaling.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

AnalogInputs configured(AnalogInputConfiguration config) {
    AnalogInputs inputs;
    EXPECT_FALSE(inputs.configure(config, DigitalInputConfiguration{}));
    return inputs;
}

// 6.2.39: "Offset is applied before gain": (2.5 V + 0.1 V) · 1.2 = 3.12 V.
TEST(Escon2AnalogInputs, AdjustmentAppliesTheOffsetBeforeTheGain) {
    AnalogInputConfiguration config;
    config.adjustments[0] = {.offset = 0.1, .gain = 1.2};
    AnalogInputs inputs = configured(config);
    inputs.set_voltage(1, 2.5);
    inputs.set_voltage(2, 2.5);
    EXPECT_DOUBLE_EQ(inputs.voltage(1), 3.12);
    EXPECT_DOUBLE_EQ(inputs.voltage(2), 2.5);
}

// 6.2.48: 0x31B0 = (−10 V, −5000 rpm; 10 V, 5000 rpm) makes 2.5 V a velocity of 1250 rpm, the
// adjusted 3.12 V one of 1560 rpm; the offset scaling 0x31B1 is the same line.
TEST(Escon2AnalogInputs, VelocitySetValueFollowsTheScalingOfTheAdjustedVoltage) {
    AnalogInputConfiguration config;
    config.functions = {AnalogInputFunction::VelocitySetValue,
                        AnalogInputFunction::VelocitySetValueOffset};
    AnalogInputs inputs = configured(config);
    const TwoPointScaling velocity{
        .first_input = -10, .first_value = -5000, .second_input = 10, .second_value = 5000};
    inputs.set_voltage(1, 2.5);
    EXPECT_DOUBLE_EQ(velocity.apply(*inputs.voltage_for(AnalogInputFunction::VelocitySetValue)),
                     1250);
    config.adjustments[0] = {.offset = 0.1, .gain = 1.2};
    ASSERT_FALSE(inputs.configure(config, {}));
    EXPECT_NEAR(velocity.apply(*inputs.voltage_for(AnalogInputFunction::VelocitySetValue)), 1560,
                1e-9);
    const TwoPointScaling offset{
        .first_input = 0, .first_value = 0, .second_input = 5, .second_value = 100};
    inputs.set_voltage(2, -1);
    EXPECT_DOUBLE_EQ(offset.apply(*inputs.voltage_for(AnalogInputFunction::VelocitySetValueOffset)),
                     -20);
    EXPECT_FALSE(inputs.voltage_for(AnalogInputFunction::CurrentSetValue));
}

// 6.2.50: the current set value, e.g. (0 V, 0 A; 10 V, 3 A) at 4 V: 1.2 A.
TEST(Escon2AnalogInputs, CurrentSetValueFollowsItsScaling) {
    AnalogInputConfiguration config;
    config.functions = {AnalogInputFunction::None, AnalogInputFunction::CurrentSetValue};
    AnalogInputs inputs = configured(config);
    inputs.set_voltage(2, 4);
    const TwoPointScaling current{
        .first_input = 0, .first_value = 0, .second_input = 10, .second_value = 3};
    EXPECT_DOUBLE_EQ(current.apply(*inputs.voltage_for(AnalogInputFunction::CurrentSetValue)), 1.2);
}

// 6.2.38: shown only on an input configured as general purpose.
TEST(Escon2AnalogInputs, GeneralPurposeValueOnlyWhereConfigured) {
    AnalogInputs inputs; // defaults (table 67): input 1 general purpose A, input 2 B
    inputs.set_voltage(1, -3.3);
    inputs.set_voltage(2, 7);
    EXPECT_DOUBLE_EQ(inputs.general_purpose(AnalogInputFunction::GeneralPurposeA), -3.3);
    EXPECT_DOUBLE_EQ(inputs.general_purpose(AnalogInputFunction::GeneralPurposeB), 7);
    AnalogInputConfiguration config;
    config.functions = {AnalogInputFunction::None, AnalogInputFunction::GeneralPurposeA};
    ASSERT_FALSE(inputs.configure(config, {}));
    EXPECT_DOUBLE_EQ(inputs.general_purpose(AnalogInputFunction::GeneralPurposeA), 7);
    EXPECT_EQ(inputs.general_purpose(AnalogInputFunction::GeneralPurposeB), 0);
}

// 6.2.40: the raw value is the pin in ADC counts over the input range, before the adjustment;
// a pin beyond the range reads the range's end.
TEST(Escon2AnalogInputs, RawValueCountsThePinOverTheRange) {
    AnalogInputConfiguration config;
    config.adjustments[0] = {.offset = 1, .gain = 2};
    AnalogInputs inputs = configured(config);
    inputs.set_voltage(1, -10);
    EXPECT_EQ(inputs.raw_value(1), 0);
    inputs.set_voltage(1, 0);
    EXPECT_EQ(inputs.raw_value(1), 2048);
    inputs.set_voltage(1, 12);
    EXPECT_EQ(inputs.raw_value(1), 4095);
    EXPECT_DOUBLE_EQ(inputs.voltage(1), 22);
    AnalogInputs nano(0, 5); // ESCON2 Nano 24/2 (table 73)
    nano.set_voltage(1, -1);
    EXPECT_EQ(nano.voltage(1), 0);
}

// Table 68: each function once; [a] / [e]: one input (analog or digital) per target.
TEST(Escon2AnalogInputs, ConflictingSetValueSourcesAreRefused) {
    AnalogInputConfiguration both;
    both.functions = {AnalogInputFunction::CurrentSetValue, AnalogInputFunction::CurrentSetValue};
    EXPECT_TRUE(configuration_error(both, {}));

    AnalogInputConfiguration velocity;
    velocity.functions = {AnalogInputFunction::VelocitySetValue, AnalogInputFunction::None};
    DigitalInputConfiguration pwm;
    pwm.functions[0] = InputFunction::PwmVelocitySetValue;
    AnalogInputs inputs;
    const std::optional<std::string> error = inputs.configure(velocity, pwm);
    ASSERT_TRUE(error);
    EXPECT_NE(error->find("digital input 1"), std::string::npos) << *error;
    EXPECT_EQ(inputs.configuration().functions[0], AnalogInputFunction::GeneralPurposeA);

    DigitalInputConfiguration switches;
    switches.functions[3] = InputFunction::VelocitySetValueSwitch1;
    EXPECT_TRUE(configuration_error(velocity, switches));
    DigitalInputConfiguration offset;
    offset.functions[1] = InputFunction::PwmVelocitySetValueOffset; // another target
    EXPECT_FALSE(configuration_error(velocity, offset));
}

TEST(Escon2AnalogInputs, ReservedCodesAndUnknownInputs) {
    EXPECT_EQ(analog_input_function_from_code(11), AnalogInputFunction::VelocitySetValueOffset);
    EXPECT_FALSE(analog_input_function_from_code(2));
    EXPECT_FALSE(analog_input_function_from_code(12));
    AnalogInputs inputs;
    EXPECT_THROW(inputs.set_voltage(3, 0), std::out_of_range);
    EXPECT_THROW(AnalogInputs(5, 5), std::invalid_argument);
}

} // namespace
} // namespace eposp::drives::escon2
