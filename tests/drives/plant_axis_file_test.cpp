// The machine file of `eposp drive epos2 --config`: examples/epos2-drive/linear-axis.yaml and
// the errors a user gets for a bad file.
#include "eposp/drives/epos2/epos2_dictionary.hpp"
#include "eposp/drives/plant/axis_file.hpp"
#include "eposp/drives/plant/reference_axis.hpp"

#include <fmt/format.h>
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
    EXPECT_FALSE(axis->encoder_mounting.on_gear_output);
    EXPECT_FALSE(axis->encoder_mounting.counts_against_motor);
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

// 8.2.74: with a gear the main sensor sits on the gear's output; either way round (table 8-104).
TEST(AxisFile, EncoderSaysWhereItIsMountedAndWhichWayItCounts) {
    const auto axis = parse_axis_file(
        "encoder: {mounted_on: gear_output, counts_against_motor: true}\n", "m.yaml");
    ASSERT_TRUE(axis) << axis.error();
    EXPECT_TRUE(axis->encoder_mounting.on_gear_output);
    EXPECT_TRUE(axis->encoder_mounting.counts_against_motor);
    const auto motor_shaft = parse_axis_file("encoder: {mounted_on: motor_shaft}\n", "m.yaml");
    ASSERT_TRUE(motor_shaft) << motor_shaft.error();
    EXPECT_FALSE(motor_shaft->encoder_mounting.on_gear_output);
    EXPECT_FALSE(reference_axis().encoder_mounting.on_gear_output);
    EXPECT_FALSE(reference_axis().encoder_mounting.counts_against_motor);
}

TEST(AxisFile, BadFilesAreUserErrorsWithTheirPlace) {
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {"motor:\n  resistance: 2\n", "m.yaml:2:3: error: unknown key 'resistance' in 'motor'"},
        {"motor:\n  type: stepper\n", "m.yaml:2:9: error: motor.type must be 'dc' or 'ec'"},
        {"encoder: {pulses: many}\n", "encoder.pulses must be an integer in 16 … 2500000"},
        {"encoder: {pulses: 8}\n", "encoder.pulses must be an integer in 16 … 2500000"},
        {"encoder:\n  mounted_on: load\n",
         "m.yaml:2:15: error: encoder.mounted_on must be 'motor_shaft' or 'gear_output'"},
        {"encoder: {counts_against_motor: 2}\n", "encoder.counts_against_motor"},
        {"gains:\n  current: {p: 40000}\n",
         "m.yaml:2:16: error: gains.current.p must be an integer in 0 … 32767 (0x60F6 sub 1)"},
        {"motor: {terminal_resistance: 0}\n",
         "m.yaml:1:30: error: motor.terminal_resistance must be a number in 0.001 … 1000 Ω"},
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

std::int64_t as_integer(canopen::DataType type, const canopen::Bytes& bytes) {
    switch (type) {
    case canopen::DataType::Integer16:
        return canopen::decode<std::int16_t>(bytes);
    case canopen::DataType::Unsigned8:
        return canopen::decode<std::uint8_t>(bytes);
    case canopen::DataType::Unsigned16:
        return canopen::decode<std::uint16_t>(bytes);
    case canopen::DataType::Unsigned32:
        return canopen::decode<std::uint32_t>(bytes);
    default:
        throw std::invalid_argument("as_integer: not a type of the machine file's entries");
    }
}

// A key that becomes a dictionary default takes exactly the values an SDO write of its entry
// takes: `gains: {current: {p: -1}}` once put 0xFFFF into 0x60F6 sub 1 and the motor ran away.
TEST(AxisFile, DictionaryValuesHaveTheRangeOfAnSdoWriteOfTheirEntry) {
    const struct {
        const char* file; ///< with {} for the value, on line 2
        std::uint16_t index;
        std::uint8_t sub;
    } keys[] = {
        {"encoder:\n  pulses: {}\n", 0x2210, 1},
        {"gains:\n  current: {{p: {}}}\n", 0x60F6, 1},
        {"gains:\n  current: {{i: {}}}\n", 0x60F6, 2},
        {"gains:\n  velocity: {{p: {}}}\n", 0x60F9, 1},
        {"gains:\n  velocity: {{i: {}}}\n", 0x60F9, 2},
        {"gains:\n  velocity: {{velocity_feed_forward: {}}}\n", 0x60F9, 4},
        {"gains:\n  velocity: {{acceleration_feed_forward: {}}}\n", 0x60F9, 5},
        {"gains:\n  position: {{p: {}}}\n", 0x60FB, 1},
        {"gains:\n  position: {{i: {}}}\n", 0x60FB, 2},
        {"gains:\n  position: {{d: {}}}\n", 0x60FB, 3},
        {"gains:\n  position: {{velocity_feed_forward: {}}}\n", 0x60FB, 4},
        {"gains:\n  position: {{acceleration_feed_forward: {}}}\n", 0x60FB, 5},
        {"gains:\n  output_current_limit: {}\n", 0x6410, 2},
        {"motor:\n  pole_pairs: {}\n", 0x6410, 3},
    };
    epos2::Epos2DictionaryConfig config;
    config.parameter_file = "never-written.bin";
    const epos2::Epos2Dictionary dictionary(std::move(config));
    for (const auto& key : keys) {
        const canopen::SubObject& entry = *dictionary.objects().find(key.index, key.sub);
        const std::int64_t low = as_integer(entry.type, *entry.low_limit);
        const std::int64_t high = as_integer(entry.type, *entry.high_limit);
        const auto file = [&key](std::int64_t value) {
            return fmt::format(fmt::runtime(key.file), value);
        };
        EXPECT_TRUE(parse_axis_file(file(low), "m.yaml")) << file(low);
        EXPECT_TRUE(parse_axis_file(file(high), "m.yaml")) << file(high);
        const std::string range =
            fmt::format("{} … {} (0x{:04X} sub {})", low, high, key.index, key.sub);
        for (const std::int64_t outside : {low - 1, high + 1}) {
            const auto axis = parse_axis_file(file(outside), "m.yaml");
            ASSERT_FALSE(axis) << file(outside);
            EXPECT_THAT(axis.error(), testing::StartsWith("m.yaml:2:"));
            EXPECT_THAT(axis.error(), HasSubstr(range));
        }
    }
    const auto runaway = parse_axis_file("gains: {current: {p: -1, i: -1}}\n", "m.yaml");
    ASSERT_FALSE(runaway);
    EXPECT_EQ(runaway.error(), "m.yaml:1:22: error: gains.current.p must be an integer in 0 … "
                               "32767 (0x60F6 sub 1)");
}

// Physical values are finite and plausible (docs/epos2.md, "The machine file").
TEST(AxisFile, PhysicalValuesOutsideTheirPlausibleRangeAreRefused) {
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {"motor:\n  terminal_resistance: .inf\n",
         "m.yaml:2:24: error: motor.terminal_resistance must be a number in 0.001 … 1000 Ω"},
        {"motor:\n  terminal_resistance: 1e300\n", "m.yaml:2:24: error:"},
        {"motor:\n  terminal_inductance: .nan\n",
         "motor.terminal_inductance must be a number in 0.001 … 1000 mH"},
        {"motor:\n  rotor_inertia: 1e-20\n",
         "m.yaml:2:18: error: motor.rotor_inertia must be a number in 0.001 … 100000 g·cm²"},
        {"motor:\n  torque_constant: -23\n", "motor.torque_constant must be a number in"},
        {"motor:\n  speed_constant: [408]\n", "motor.speed_constant must be a number in"},
        {"load:\n  coulomb_friction: 1e30\n",
         "m.yaml:2:21: error: load.coulomb_friction must be a number in 0 … 100000 mN·m"},
        {"load:\n  viscous_friction: 1e30\n", "load.viscous_friction must be a number in 0 … 100"},
        {"load:\n  inertia: -1\n", "load.inertia must be a number in 0 … 1000000000 g·cm²"},
        {"gearhead:\n  ratio: 1e-9\n", "gearhead.ratio must be a number in 0.1 … 10000"},
        {"gearhead:\n  efficiency: 1.5\n", "gearhead.efficiency must be a number in 0.01 … 1"},
        {"power_stage:\n  supply_voltage: -.inf\n", "supply_voltage must be a number in 1 … 100 V"},
        {"power_stage:\n  overcurrent: 0\n", "overcurrent must be a number in 0.1 … 100 A"},
        {"power_stage:\n  max_duty: 2\n", "max_duty must be a number in 0.01 … 1"},
    };
    for (const auto& bad : cases) {
        const auto axis = parse_axis_file(bad.text, "m.yaml");
        ASSERT_FALSE(axis) << bad.text;
        EXPECT_THAT(axis.error(), HasSubstr(bad.message)) << bad.text;
    }
}

// docs/epos2.md: "limits the wrong way round" are refused; positions are INTEGER32 quadcounts.
TEST(AxisFile, SwitchesTheWrongWayRoundOrOutOfRangeAreRefused) {
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {"switches:\n  negative_limit: 1000\n  positive_limit: -1000\n",
         "m.yaml:2:19: error: switches.negative_limit (1000) must lie below "
         "switches.positive_limit (-1000)"},
        {"switches: {negative_limit: 5, positive_limit: 5}\n", "must lie below"},
        {"switches:\n  home: 3000000000\n",
         "m.yaml:2:9: error: switches.home must be an integer in -2147483648 … 2147483647"},
        {"switches:\n  home_length: 0\n", "switches.home_length must be an integer in 1 …"},
    };
    for (const auto& bad : cases) {
        const auto axis = parse_axis_file(bad.text, "m.yaml");
        ASSERT_FALSE(axis) << bad.text;
        EXPECT_THAT(axis.error(), HasSubstr(bad.message)) << bad.text;
    }
    EXPECT_TRUE(parse_axis_file("switches: {negative_limit: -5, positive_limit: 5}\n", "m.yaml"));
}

// A key given twice and a second document would be read silently (the last value, the first
// document): both are errors at their place.
TEST(AxisFile, DuplicateKeysAndASecondDocumentAreRefused) {
    const struct {
        const char* text;
        const char* message;
    } cases[] = {
        {"motor:\n  terminal_resistance: 2\n  terminal_resistance: 3\n",
         "m.yaml:3:3: error: duplicate key 'terminal_resistance' in 'motor'"},
        {"encoder: {pulses: 500}\nencoder: {pulses: 512}\n",
         "m.yaml:2:1: error: duplicate key 'encoder' in 'the file'"},
        {"gains:\n  current: {p: 1, p: 2}\n", "duplicate key 'p' in 'gains.current'"},
        {"encoder: {pulses: 500}\n---\nencoder: {pulses: 512}\n",
         "m.yaml:2:1: error: a second YAML document: a file holds one"},
        {"encoder: {pulses: 500}\n---\n- [1\n", "m.yaml:"},
    };
    for (const auto& bad : cases) {
        const auto axis = parse_axis_file(bad.text, "m.yaml");
        ASSERT_FALSE(axis) << bad.text;
        EXPECT_THAT(axis.error(), HasSubstr(bad.message)) << bad.text;
    }
}

} // namespace
} // namespace eposp::drives::plant
