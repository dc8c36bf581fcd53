#include "eposp/drives/plant/axis_file.hpp"

#include "axis_file_limits.hpp"
#include "eposp/drives/plant/reference_axis.hpp"
#include "eposp/yaml/reader.hpp"

#include <cmath>
#include <fmt/format.h>
#include <string>

namespace eposp::drives::plant {
namespace {

namespace limits = axis_file_limits;

// Data-sheet units to SI.
constexpr double kMilli = 1e-3;
constexpr double kGramSquareCentimetre = 1e-7; ///< kg·m²

using yaml::Reader;

/// A physical quantity in the file's unit, times `unit` for SI.
auto quantity(Reader& in, double& field, std::string what, limits::Quantity range,
              double unit = 1.0) {
    return [&in, &field, what = std::move(what), range, unit](const YAML::Node& value) {
        double number = 0;
        if (!value.IsScalar() || !YAML::convert<double>::decode(value, number) ||
            !std::isfinite(number) || number < range.low || number > range.high) {
            in.fail(value, fmt::format("{} must be a number in {} … {}{}{}", what, range.low,
                                       range.high, range.unit.empty() ? "" : " ", range.unit));
        }
        field = number * unit;
    };
}

/// An integer that becomes a dictionary default: what an SDO write of the entry takes.
template <typename T>
auto dictionary_value(Reader& in, T& field, std::string what, limits::DictionaryValue entry) {
    return [&in, &field, what = std::move(what), entry](const YAML::Node& value) {
        std::int64_t number = 0;
        if (!value.IsScalar() || !YAML::convert<std::int64_t>::decode(value, number) ||
            number < entry.low || number > entry.high) {
            in.fail(value, fmt::format("{} must be an integer in {} … {} (0x{:04X} sub {})", what,
                                       entry.low, entry.high, entry.index, entry.sub));
        }
        field = static_cast<T>(number);
    };
}

/// A switch position in quadcounts.
auto position(Reader& in, std::optional<std::int64_t>& field, std::string what,
              std::int64_t low = limits::kPositionLow) {
    return [&in, &field, what = std::move(what), low](const YAML::Node& value) {
        std::int64_t number = 0;
        if (!value.IsScalar() || !YAML::convert<std::int64_t>::decode(value, number) ||
            number < low || number > limits::kPositionHigh) {
            in.fail(value, fmt::format("{} must be an integer in {} … {} (quadcounts)", what, low,
                                       limits::kPositionHigh));
        }
        field = number;
    };
}

void read_motor(Reader& in, const YAML::Node& node, MotorParameters& motor) {
    in.each_key(node, "motor",
                {{"type",
                  [&](const YAML::Node& value) {
                      const auto type = in.scalar<std::string>(value, "motor.type");
                      if (type != "dc" && type != "ec") {
                          in.fail(value, "motor.type must be 'dc' or 'ec'");
                      }
                      motor.kind = type == "dc" ? MotorKind::BrushedDc : MotorKind::Ec;
                  }},
                 {"terminal_resistance",
                  quantity(in, motor.terminal_resistance, "motor.terminal_resistance",
                           limits::kTerminalResistance)},
                 {"terminal_inductance",
                  quantity(in, motor.terminal_inductance, "motor.terminal_inductance",
                           limits::kTerminalInductance, kMilli)},
                 {"torque_constant", quantity(in, motor.torque_constant, "motor.torque_constant",
                                              limits::kTorqueConstant, kMilli)},
                 {"speed_constant", quantity(in, motor.speed_constant, "motor.speed_constant",
                                             limits::kSpeedConstant)},
                 {"rotor_inertia", quantity(in, motor.rotor_inertia, "motor.rotor_inertia",
                                            limits::kRotorInertia, kGramSquareCentimetre)},
                 {"pole_pairs",
                  dictionary_value(in, motor.pole_pairs, "motor.pole_pairs", limits::kPolePairs)}});
}

void read_encoder(Reader& in, const YAML::Node& node, AxisParameters& axis) {
    EncoderMounting& mounting = axis.encoder_mounting;
    in.each_key(
        node, "encoder",
        {{"pulses",
          dictionary_value(in, axis.encoder_pulses, "encoder.pulses", limits::kEncoderPulses)},
         {"mounted_on",
          [&](const YAML::Node& value) {
              const auto shaft = in.scalar<std::string>(value, "encoder.mounted_on");
              if (shaft != "motor_shaft" && shaft != "gear_output") {
                  in.fail(value, "encoder.mounted_on must be 'motor_shaft' or 'gear_output'");
              }
              mounting.on_gear_output = shaft == "gear_output";
          }},
         {"counts_against_motor", [&](const YAML::Node& value) {
              mounting.counts_against_motor =
                  in.scalar<bool>(value, "encoder.counts_against_motor");
          }}});
}

void read_gains(Reader& in, const YAML::Node& node, ServoGains& gains) {
    // The parameter sets in the dictionary's integer units (docs/drive-motion-and-plant.md).
    CurrentControlParameterSet current = to_parameter_set(gains.current);
    VelocityControlParameterSet velocity = to_parameter_set(gains.velocity);
    PositionControlParameterSet position = to_parameter_set(gains.position);
    int current_limit_ma = static_cast<int>(std::lround(gains.current_limit / kMilli));
    in.each_key(node, "gains",
                {{"current",
                  [&](const YAML::Node& sub) {
                      in.each_key(sub, "gains.current",
                                  {{"p", dictionary_value(in, current.p_gain, "gains.current.p",
                                                          limits::kCurrentP)},
                                   {"i", dictionary_value(in, current.i_gain, "gains.current.i",
                                                          limits::kCurrentI)}});
                  }},
                 {"velocity",
                  [&](const YAML::Node& sub) {
                      in.each_key(sub, "gains.velocity",
                                  {{"p", dictionary_value(in, velocity.p_gain, "gains.velocity.p",
                                                          limits::kVelocityP)},
                                   {"i", dictionary_value(in, velocity.i_gain, "gains.velocity.i",
                                                          limits::kVelocityI)},
                                   {"velocity_feed_forward",
                                    dictionary_value(in, velocity.velocity_feed_forward,
                                                     "gains.velocity.velocity_feed_forward",
                                                     limits::kVelocityFeedForward)},
                                   {"acceleration_feed_forward",
                                    dictionary_value(in, velocity.acceleration_feed_forward,
                                                     "gains.velocity.acceleration_feed_forward",
                                                     limits::kVelocityAccelerationFeedForward)}});
                  }},
                 {"position",
                  [&](const YAML::Node& sub) {
                      in.each_key(sub, "gains.position",
                                  {{"p", dictionary_value(in, position.p_gain, "gains.position.p",
                                                          limits::kPositionP)},
                                   {"i", dictionary_value(in, position.i_gain, "gains.position.i",
                                                          limits::kPositionI)},
                                   {"d", dictionary_value(in, position.d_gain, "gains.position.d",
                                                          limits::kPositionD)},
                                   {"velocity_feed_forward",
                                    dictionary_value(in, position.velocity_feed_forward,
                                                     "gains.position.velocity_feed_forward",
                                                     limits::kPositionFeedForward)},
                                   {"acceleration_feed_forward",
                                    dictionary_value(in, position.acceleration_feed_forward,
                                                     "gains.position.acceleration_feed_forward",
                                                     limits::kPositionAccelerationFeedForward)}});
                  }},
                 {"output_current_limit", // mA
                  dictionary_value(in, current_limit_ma, "gains.output_current_limit",
                                   limits::kOutputCurrentLimit)}});
    gains.current = to_si(current);
    gains.velocity = to_si(velocity);
    gains.position = to_si(position);
    gains.current_limit = current_limit_ma * kMilli;
}

void read_switches(Reader& in, const YAML::Node& node, SwitchLayout& switches) {
    in.each_key(
        node, "switches",
        {{"negative_limit", position(in, switches.negative_limit, "switches.negative_limit")},
         {"positive_limit", position(in, switches.positive_limit, "switches.positive_limit")},
         {"home", position(in, switches.home, "switches.home")},
         {"home_length", position(in, switches.home_length, "switches.home_length", 1)},
         {"home_active_above", [&](const YAML::Node& value) {
              switches.home_active_above = in.scalar<bool>(value, "switches.home_active_above");
          }}});
    // "Pressed at and beyond": limits the wrong way round (or on one position) leave no travel.
    if (switches.negative_limit && switches.positive_limit &&
        *switches.negative_limit >= *switches.positive_limit) {
        in.fail(node["negative_limit"],
                fmt::format("switches.negative_limit ({}) must lie below switches.positive_limit "
                            "({})",
                            *switches.negative_limit, *switches.positive_limit));
    }
}

AxisParameters read_axis(Reader& in, const YAML::Node& root) {
    AxisParameters axis = reference_axis();
    if (root.IsNull()) {
        return axis; // an empty file: the reference axis
    }
    in.each_key(
        root, "the file",
        {{"motor",
          [&](const YAML::Node& node) {
              read_motor(in, node, axis.plant.motor);
          }},
         {"gearhead",
          [&](const YAML::Node& node) {
              GearheadParameters& gearhead = axis.plant.gearhead;
              in.each_key(
                  node, "gearhead",
                  {{"ratio", quantity(in, gearhead.ratio, "gearhead.ratio", limits::kGearRatio)},
                   {"efficiency", quantity(in, gearhead.efficiency, "gearhead.efficiency",
                                           limits::kGearEfficiency)}});
          }},
         {"encoder",
          [&](const YAML::Node& node) {
              read_encoder(in, node, axis);
          }},
         {"load",
          [&](const YAML::Node& node) {
              LoadParameters& load = axis.plant.load;
              in.each_key(
                  node, "load",
                  {{"inertia", quantity(in, load.inertia, "load.inertia", limits::kLoadInertia,
                                        kGramSquareCentimetre)},
                   {"viscous_friction", quantity(in, load.viscous_friction, "load.viscous_friction",
                                                 limits::kViscousFriction)},
                   {"coulomb_friction", quantity(in, load.coulomb_friction, "load.coulomb_friction",
                                                 limits::kCoulombFriction, kMilli)}});
          }},
         {"power_stage",
          [&](const YAML::Node& node) {
              PowerStageParameters& stage = axis.plant.power_stage;
              in.each_key(
                  node, "power_stage",
                  {{"supply_voltage",
                    quantity(in, stage.supply_voltage, "power_stage.supply_voltage",
                             limits::kSupplyVoltage)},
                   {"max_duty",
                    quantity(in, stage.max_duty, "power_stage.max_duty", limits::kMaxDuty)},
                   {"min_supply_voltage",
                    quantity(in, stage.min_supply_voltage, "power_stage.min_supply_voltage",
                             limits::kSupplyLimit)},
                   {"max_supply_voltage",
                    quantity(in, stage.max_supply_voltage, "power_stage.max_supply_voltage",
                             limits::kSupplyLimit)},
                   {"overcurrent", quantity(in, stage.overcurrent, "power_stage.overcurrent",
                                            limits::kOvercurrent)}});
          }},
         {"gains",
          [&](const YAML::Node& node) {
              read_gains(in, node, axis.gains);
          }},
         {"switches", [&](const YAML::Node& node) {
              read_switches(in, node, axis.switches);
          }}});
    if (const auto valid = validate(axis.plant); !valid) {
        in.fail(root, valid.error());
    }
    return axis;
}

} // namespace

core::Result<AxisParameters> parse_axis_file(std::string_view text, std::string_view source) {
    return yaml::parse<AxisParameters>(text, source, read_axis);
}

core::Result<AxisParameters> load_axis_file(const std::filesystem::path& path) {
    auto text = yaml::read_text(path);
    if (!text) {
        return core::Error{text.error()};
    }
    return parse_axis_file(*text, path.string());
}

} // namespace eposp::drives::plant
