#include "eposp/drives/plant/axis_file.hpp"

#include "eposp/drives/plant/reference_axis.hpp"
#include "eposp/yaml/reader.hpp"

#include <fmt/format.h>
#include <string>

namespace eposp::drives::plant {
namespace {

// Data-sheet units to SI.
constexpr double kMilli = 1e-3;
constexpr double kGramSquareCentimetre = 1e-7; ///< kg·m²

using yaml::Reader;

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
                 {"terminal_resistance", // Ω
                  [&](const YAML::Node& value) {
                      motor.terminal_resistance = in.scalar<double>(value, "terminal_resistance");
                  }},
                 {"terminal_inductance", // mH
                  [&](const YAML::Node& value) {
                      motor.terminal_inductance =
                          in.scalar<double>(value, "terminal_inductance") * kMilli;
                  }},
                 {"torque_constant", // mN·m/A
                  [&](const YAML::Node& value) {
                      motor.torque_constant = in.scalar<double>(value, "torque_constant") * kMilli;
                  }},
                 {"speed_constant", // rpm/V
                  [&](const YAML::Node& value) {
                      motor.speed_constant = in.scalar<double>(value, "speed_constant");
                  }},
                 {"rotor_inertia", // g·cm²
                  [&](const YAML::Node& value) {
                      motor.rotor_inertia =
                          in.scalar<double>(value, "rotor_inertia") * kGramSquareCentimetre;
                  }},
                 {"pole_pairs", [&](const YAML::Node& value) {
                      motor.pole_pairs = in.scalar<int>(value, "pole_pairs");
                  }}});
}

void read_gains(Reader& in, const YAML::Node& node, ServoGains& gains) {
    // The parameter sets in the dictionary's integer units (docs/drive-motion-and-plant.md).
    CurrentControlParameterSet current = to_parameter_set(gains.current);
    VelocityControlParameterSet velocity = to_parameter_set(gains.velocity);
    PositionControlParameterSet position = to_parameter_set(gains.position);
    const auto set = [&in](auto& field, std::string_view what) {
        return [&in, &field, what](const YAML::Node& value) {
            field = in.scalar<std::remove_reference_t<decltype(field)>>(value, what);
        };
    };
    in.each_key(
        node, "gains",
        {{"current",
          [&](const YAML::Node& sub) {
              in.each_key(sub, "gains.current",
                          {{"p", set(current.p_gain, "current p")},
                           {"i", set(current.i_gain, "current i")}});
          }},
         {"velocity",
          [&](const YAML::Node& sub) {
              in.each_key(sub, "gains.velocity",
                          {{"p", set(velocity.p_gain, "velocity p")},
                           {"i", set(velocity.i_gain, "velocity i")},
                           {"velocity_feed_forward",
                            set(velocity.velocity_feed_forward, "velocity_feed_forward")},
                           {"acceleration_feed_forward",
                            set(velocity.acceleration_feed_forward, "acceleration_feed_forward")}});
          }},
         {"position",
          [&](const YAML::Node& sub) {
              in.each_key(sub, "gains.position",
                          {{"p", set(position.p_gain, "position p")},
                           {"i", set(position.i_gain, "position i")},
                           {"d", set(position.d_gain, "position d")},
                           {"velocity_feed_forward",
                            set(position.velocity_feed_forward, "velocity_feed_forward")},
                           {"acceleration_feed_forward",
                            set(position.acceleration_feed_forward, "acceleration_feed_forward")}});
          }},
         {"output_current_limit", [&](const YAML::Node& value) { // mA
              gains.current_limit = in.scalar<double>(value, "output_current_limit") * kMilli;
          }}});
    gains.current = to_si(current);
    gains.velocity = to_si(velocity);
    gains.position = to_si(position);
}

void read_switches(Reader& in, const YAML::Node& node, SwitchLayout& switches) {
    const auto position = [&in](std::optional<std::int64_t>& field, std::string_view what) {
        return [&in, &field, what](const YAML::Node& value) {
            field = in.scalar<std::int64_t>(value, what);
        };
    };
    in.each_key(node, "switches",
                {{"negative_limit", position(switches.negative_limit, "negative_limit")},
                 {"positive_limit", position(switches.positive_limit, "positive_limit")},
                 {"home", position(switches.home, "home")},
                 {"home_length", position(switches.home_length, "home_length")},
                 {"home_active_above", [&](const YAML::Node& value) {
                      switches.home_active_above = in.scalar<bool>(value, "home_active_above");
                  }}});
}

AxisParameters read_axis(Reader& in, const YAML::Node& root) {
    AxisParameters axis = reference_axis();
    if (root.IsNull()) {
        return axis; // an empty file: the reference axis
    }
    const auto number = [&in](double& field, std::string_view what, double unit = 1.0) {
        return [&in, &field, what, unit](const YAML::Node& value) {
            field = in.scalar<double>(value, what) * unit;
        };
    };
    in.each_key(
        root, "the file",
        {{"motor",
          [&](const YAML::Node& node) {
              read_motor(in, node, axis.plant.motor);
          }},
         {"gearhead",
          [&](const YAML::Node& node) {
              in.each_key(node, "gearhead",
                          {{"ratio", number(axis.plant.gearhead.ratio, "ratio")},
                           {"efficiency", number(axis.plant.gearhead.efficiency, "efficiency")}});
          }},
         {"encoder",
          [&](const YAML::Node& node) {
              in.each_key(node, "encoder", {{"pulses", [&](const YAML::Node& value) {
                                                 axis.encoder_pulses =
                                                     in.scalar<int>(value, "encoder.pulses");
                                                 if (axis.encoder_pulses < 16) {
                                                     in.fail(value, "encoder.pulses must be at "
                                                                    "least 16 (8.2.74)");
                                                 }
                                             }}});
          }},
         {"load",
          [&](const YAML::Node& node) {
              LoadParameters& load = axis.plant.load;
              in.each_key(node, "load",
                          {{"inertia", number(load.inertia, "inertia", kGramSquareCentimetre)},
                           {"viscous_friction", number(load.viscous_friction, "viscous_friction")},
                           {"coulomb_friction",
                            number(load.coulomb_friction, "coulomb_friction", kMilli)}});
          }},
         {"power_stage",
          [&](const YAML::Node& node) {
              PowerStageParameters& stage = axis.plant.power_stage;
              in.each_key(
                  node, "power_stage",
                  {{"supply_voltage", number(stage.supply_voltage, "supply_voltage")},
                   {"max_duty", number(stage.max_duty, "max_duty")},
                   {"min_supply_voltage", number(stage.min_supply_voltage, "min_supply_voltage")},
                   {"max_supply_voltage", number(stage.max_supply_voltage, "max_supply_voltage")},
                   {"overcurrent", number(stage.overcurrent, "overcurrent")}});
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
