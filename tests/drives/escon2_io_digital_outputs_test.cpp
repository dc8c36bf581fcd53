// The ESCON2's digital outputs (ESCON2 FW spec 4.2, 6.2.33 - 6.2.35, 6.2.78): ready/fault,
// limitation, general purpose A - C, polarity and the hall sensor frequency outputs.
#include "eposp/drives/escon2/io/digital_outputs.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace eposp::drives::escon2 {
namespace {

DigitalOutputs with(std::array<OutputFunction, kDigitalOutputCount> functions,
                    std::uint16_t polarity = 0) {
    DigitalOutputs outputs;
    DigitalOutputConfiguration config;
    config.functions = functions;
    config.polarity = polarity;
    EXPECT_FALSE(outputs.configure(config));
    return outputs;
}

// Table 66: ready/fault is active unless in Fault / Fault reaction active.
TEST(Escon2DigitalOutputs, ReadyFaultIsInactiveOnAFault) {
    DigitalOutputs outputs =
        with({OutputFunction::ReadyFault, OutputFunction::None, OutputFunction::None});
    EXPECT_EQ(outputs.logic_state(), 0x1);
    EXPECT_EQ(outputs.functionality(), 1U << 25);
    outputs.set_device_state(true, false);
    EXPECT_EQ(outputs.logic_state(), 0x0);
    EXPECT_FALSE(outputs.pin(1));
}

// Table 66: limitation follows statusword bit 11.
TEST(Escon2DigitalOutputs, LimitationFollowsTheInternalLimit) {
    DigitalOutputs outputs =
        with({OutputFunction::None, OutputFunction::Limitation, OutputFunction::None});
    EXPECT_EQ(outputs.logic_state(), 0x0);
    outputs.set_device_state(false, true);
    EXPECT_EQ(outputs.logic_state(), 0x2);
    EXPECT_TRUE(outputs.pin(2));
}

// 6.2.35 / 6.2.78: the host writes general purpose A - C; the device's bits and 24 - 31 are not
// taken from a write.
TEST(Escon2DigitalOutputs, HostWritesTheGeneralPurposeOutputs) {
    DigitalOutputs outputs = with({OutputFunction::GeneralPurposeA, OutputFunction::GeneralPurposeB,
                                   OutputFunction::GeneralPurposeC});
    outputs.set_device_state(true, false);
    outputs.write_general_purpose(0xFF05'0000 | (1U << 26));
    EXPECT_EQ(outputs.cia_outputs(), 0x0005'0000U);
    EXPECT_EQ(outputs.functionality(), 0x0005'0000U);
    EXPECT_EQ(outputs.logic_state(), 0b101);
}

// 6.2.33.2: a polarity bit inverts the pin; "not configured pins will remain zero".
TEST(Escon2DigitalOutputs, PolarityInvertsConfiguredOutputsOnly) {
    DigitalOutputs outputs = with(
        {OutputFunction::GeneralPurposeA, OutputFunction::None, OutputFunction::GeneralPurposeC},
        0b111);
    outputs.write_general_purpose(1U << 16);
    EXPECT_EQ(outputs.logic_state(), 0b100);
}

// Table 65: frequency outputs on DigOut1/2 only, with a hall sensor, one at a time; each
// functionality once; 6.2.34: sensor 2 disables the high-speed output.
TEST(Escon2DigitalOutputs, ConfigurationRulesOfTable65) {
    DigitalOutputConfiguration config;
    config.functions = {OutputFunction::None, OutputFunction::None,
                        OutputFunction::HallSensorRotationFrequency};
    EXPECT_TRUE(configuration_error(config));
    config.functions = {OutputFunction::HallSensorRotationFrequency,
                        OutputFunction::HallSensorCommutationFrequency, OutputFunction::None};
    EXPECT_TRUE(configuration_error(config));
    config.functions = {OutputFunction::HallSensorRotationFrequency, OutputFunction::None,
                        OutputFunction::None};
    EXPECT_FALSE(configuration_error(config));
    config.hall_sensor_present = false;
    EXPECT_TRUE(configuration_error(config));
    config.functions = {OutputFunction::ReadyFault, OutputFunction::ReadyFault,
                        OutputFunction::None};
    EXPECT_TRUE(configuration_error(config));

    DigitalOutputs outputs;
    EXPECT_TRUE(outputs.configure(config));
    EXPECT_EQ(outputs.configuration().functions[0], OutputFunction::GeneralPurposeA); // kept
    config.functions = {OutputFunction::None, OutputFunction::None, OutputFunction::ReadyFault};
    config.sensor2_configured = true;
    ASSERT_FALSE(outputs.configure(config));
    EXPECT_EQ(outputs.logic_state(), 0);
    EXPECT_FALSE(output_function_from_code(19));
    EXPECT_EQ(output_function_from_code(33), OutputFunction::HallSensorRotationFrequency);
}

// A frequency output shows 0 in the logic state; its pin is a square wave: 1500 rpm are 25
// turns per second, with 4 pole pairs 600 hall state changes per second.
TEST(Escon2DigitalOutputs, HallFrequencyOutputsFollowTheSpeed) {
    DigitalOutputs rotation = with(
        {OutputFunction::HallSensorRotationFrequency, OutputFunction::None, OutputFunction::None});
    rotation.step(-1500, 4, 1e-4);
    EXPECT_DOUBLE_EQ(rotation.frequency(OutputFunction::HallSensorRotationFrequency), 25);
    EXPECT_DOUBLE_EQ(rotation.frequency(OutputFunction::HallSensorCommutationFrequency), 600);
    EXPECT_EQ(rotation.logic_state(), 0);
    // Count the rising edges at the pin over one second: 25 turns.
    DigitalOutputs counted =
        with({OutputFunction::None, OutputFunction::HallSensorCommutationFrequency,
              OutputFunction::None});
    int rising = 0;
    bool before = counted.pin(2);
    for (int i = 0; i < 10'000; ++i) {
        counted.step(1500, 4, 1e-4);
        rising += counted.pin(2) && !before ? 1 : 0;
        before = counted.pin(2);
    }
    EXPECT_NEAR(rising, 600, 1);
    EXPECT_THROW(static_cast<void>(counted.pin(4)), std::out_of_range);
}

} // namespace
} // namespace eposp::drives::escon2
