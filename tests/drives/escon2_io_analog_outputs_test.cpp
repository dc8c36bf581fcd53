// The ESCON2's analog outputs (ESCON2 FW spec 4.4, 6.2.41 - 6.2.43, 6.2.52 - 6.2.54): general
// purpose voltages, the monitored values through their scaling, and the output range.
#include "eposp/drives/escon2/io/analog_outputs.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

AnalogOutputs with(AnalogOutputFunction first, AnalogOutputFunction second,
                   AnalogOutputScalings scalings = {}) {
    AnalogOutputs outputs;
    outputs.configure({.functions = {first, second}, .scalings = scalings});
    return outputs;
}

// 6.2.43: a general purpose voltage takes effect when written (4.4.1), on the output
// configured for it only.
TEST(Escon2AnalogOutputs, GeneralPurposeVoltageShowsWhenWritten) {
    AnalogOutputs outputs; // defaults (table 69): output 1 general purpose A, output 2 B
    outputs.write_general_purpose(AnalogOutputFunction::GeneralPurposeA, 1.25);
    outputs.write_general_purpose(AnalogOutputFunction::GeneralPurposeB, -2.5);
    EXPECT_EQ(outputs.voltage(1), 1.25);
    EXPECT_EQ(outputs.voltage(2), -2.5);
    outputs.configure(
        {.functions = {AnalogOutputFunction::None, AnalogOutputFunction::GeneralPurposeA},
         .scalings = {}});
    EXPECT_EQ(outputs.voltage(1), 0);
    EXPECT_EQ(outputs.voltage(2), 1.25);
    EXPECT_THROW(outputs.write_general_purpose(AnalogOutputFunction::CurrentActual, 1),
                 std::invalid_argument);
}

// 6.2.52: (−5000 rpm, −4 V; 5000 rpm, 4 V) shows 1250 rpm as 1 V, the averaged value alike.
TEST(Escon2AnalogOutputs, VelocityIsShownThroughItsScaling) {
    AnalogOutputScalings scalings;
    scalings.velocity = {
        .first_input = -5000, .first_value = -4, .second_input = 5000, .second_value = 4};
    AnalogOutputs outputs = with(AnalogOutputFunction::VelocityActual,
                                 AnalogOutputFunction::VelocityActualAveraged, scalings);
    outputs.update({.velocity = 1250, .velocity_averaged = -2500});
    EXPECT_DOUBLE_EQ(outputs.voltage(1), 1);
    EXPECT_DOUBLE_EQ(outputs.voltage(2), -2);
}

// 6.2.53: (0 A, 0 V; 2 A, 4 V): 0.5 A is 1 V; 3 A would be 6 V, limited to the range's 4 V.
TEST(Escon2AnalogOutputs, CurrentIsShownWithinTheOutputRange) {
    AnalogOutputScalings scalings;
    scalings.current = {.first_input = 0, .first_value = 0, .second_input = 2, .second_value = 4};
    AnalogOutputs outputs = with(AnalogOutputFunction::CurrentActual,
                                 AnalogOutputFunction::CurrentActualAveraged, scalings);
    outputs.update({.current = 0.5, .current_averaged = 3});
    EXPECT_DOUBLE_EQ(outputs.voltage(1), 1);
    EXPECT_DOUBLE_EQ(outputs.voltage(2), 4);
    AnalogOutputs nano(0, 3.3); // ESCON2 Nano 24/2 (table 71)
    nano.configure({.functions = {AnalogOutputFunction::CurrentActual, AnalogOutputFunction::None},
                    .scalings = scalings});
    nano.update({.current = -1});
    EXPECT_EQ(nano.voltage(1), 0);
}

// 6.2.54: each temperature through its own line, e.g. (0 °C, 0 V; 100 °C, 4 V).
TEST(Escon2AnalogOutputs, TemperaturesAreShownThroughTheirScalings) {
    AnalogOutputScalings scalings;
    scalings.logic_section_temperature = {
        .first_input = 0, .first_value = 0, .second_input = 100, .second_value = 4};
    scalings.power_stage_temperature = {
        .first_input = 20, .first_value = -4, .second_input = 120, .second_value = 4};
    AnalogOutputs outputs = with(AnalogOutputFunction::TemperatureLogicSection,
                                 AnalogOutputFunction::TemperaturePowerStage, scalings);
    outputs.update({.logic_section_temperature = 45, .power_stage_temperature = 70});
    EXPECT_DOUBLE_EQ(outputs.voltage(1), 1.8);
    EXPECT_DOUBLE_EQ(outputs.voltage(2), 0);
}

// The defaults' first and second values are all 0: "invalid scaling settings ... will output
// the voltage configured in ... first voltage" (−4 V).
TEST(Escon2AnalogOutputs, DefaultScalingOutputsTheFirstVoltage) {
    AnalogOutputs outputs =
        with(AnalogOutputFunction::VelocityActual, AnalogOutputFunction::TemperaturePowerStage);
    outputs.update({.velocity = 3000, .power_stage_temperature = 60});
    EXPECT_EQ(outputs.voltage(1), -4);
    EXPECT_EQ(outputs.voltage(2), -4);
    EXPECT_THROW(static_cast<void>(outputs.voltage(3)), std::out_of_range);
    EXPECT_FALSE(analog_output_function_from_code(14));
    EXPECT_EQ(analog_output_function_from_code(13), AnalogOutputFunction::TemperaturePowerStage);
}

} // namespace
} // namespace eposp::drives::escon2
