// The machine file of `eposp drive epos2 --config`: examples/epos2-drive/linear-axis.yaml and
// the errors a user gets for a bad file.
#include "eposp/drives/plant/axis_file.hpp"
#include "eposp/drives/plant/reference_axis.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::drives::plant {
namespace {

using testing::HasSubstr;

TEST(AxisFile, TheExampleDescribesItsMachine) {
    const auto axis =
        load_axis_file(std::string(EPOSP_SOURCE_DIR) + "/examples/epos2-drive/linear-axis.yaml");
    ASSERT_TRUE(axis) << axis.error();
    EXPECT_EQ(axis->plant.motor.kind, MotorKind::BrushedDc);
    EXPECT_DOUBLE_EQ(axis->plant.motor.terminal_inductance, 0.238e-3);
    EXPECT_DOUBLE_EQ(axis->plant.motor.torque_constant, 0.0234);
    EXPECT_DOUBLE_EQ(axis->plant.motor.rotor_inertia, 10.5e-7);
    EXPECT_DOUBLE_EQ(axis->plant.gearhead.ratio, 4.8);
    EXPECT_DOUBLE_EQ(axis->plant.load.coulomb_friction, 5e-3);
    EXPECT_EQ(axis->encoder_pulses, 500);
    EXPECT_DOUBLE_EQ(axis->gains.position.kp, 2.285);
    EXPECT_DOUBLE_EQ(axis->gains.current_limit, 3);
    EXPECT_EQ(axis->switches.negative_limit, -200000);
    EXPECT_EQ(axis->switches.home_length, 4000);
}

TEST(AxisFile, LeftOutSectionsKeepTheReferenceAxis) {
    const auto axis = parse_axis_file("encoder: {pulses: 1024}\n", "m.yaml");
    ASSERT_TRUE(axis) << axis.error();
    EXPECT_EQ(axis->encoder_pulses, 1024);
    EXPECT_DOUBLE_EQ(axis->plant.motor.terminal_resistance,
                     reference_axis().plant.motor.terminal_resistance);
    EXPECT_TRUE(parse_axis_file("", "empty.yaml"));
}

TEST(AxisFile, BadFilesAreUserErrorsWithTheirPlace) {
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {"motor:\n  resistance: 2\n", "m.yaml:2:3: error: unknown key 'resistance' in 'motor'"},
        {"motor:\n  type: stepper\n", "m.yaml:2:9: error: motor.type must be 'dc' or 'ec'"},
        {"encoder: {pulses: many}\n", "encoder.pulses must be an integer in range"},
        {"encoder: {pulses: 8}\n", "encoder.pulses must be at least 16"},
        {"gains:\n  current: {p: 40000}\n", "m.yaml:2:16: error: current p must be an integer"},
        {"motor: {terminal_resistance: 0}\n", "resistance and inductance must be positive"},
        {"power_stage: {min_supply_voltage: 30}\n", "undervoltage limit must lie below"},
        {"motor: [1, 2\n", "m.yaml:"},
        {"- 1\n", "'the file' must be a mapping"},
    };
    for (const auto& bad : cases) {
        const auto axis = parse_axis_file(bad.text, "m.yaml");
        ASSERT_FALSE(axis) << bad.text;
        EXPECT_THAT(axis.error(), HasSubstr(bad.message)) << bad.text;
    }
    EXPECT_THAT(load_axis_file("/nonexistent/m.yaml").error(), HasSubstr("cannot read"));
}

} // namespace
} // namespace eposp::drives::plant
