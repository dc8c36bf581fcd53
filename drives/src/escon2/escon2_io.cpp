#include "escon2_io.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eposp::drives::escon2 {
namespace {

constexpr std::uint32_t kSensor1Hall = 0x0000'0010;    // table 47
constexpr std::uint32_t kSensor2Encoder = 0x0000'0100; // table 47

std::int16_t millivolts(double volts) {
    return static_cast<std::int16_t>(std::clamp(std::round(volts * 1000), -32768.0, 32767.0));
}

std::int32_t rounded(double value) {
    using Limits = std::numeric_limits<std::int32_t>;
    return static_cast<std::int32_t>(
        std::clamp(std::round(value), double{Limits::min()}, double{Limits::max()}));
}

} // namespace

Escon2Io::Escon2Io(canopen::ObjectDictionary& od, double analog_input_low, double analog_input_high,
                   double analog_output_low, double analog_output_high, double now)
    : od_(od), pwm_inputs_{PwmInput(1, now), PwmInput(2, now)},
      analog_inputs_(analog_input_low, analog_input_high),
      analog_outputs_(analog_output_low, analog_output_high) {
    reload();
    watch();
}

void Escon2Io::reload() {
    configure_digital_inputs();
    configure_analog_inputs();
    configure_digital_outputs();
    configure_analog_outputs();
}

// The dictionary refuses what breaks the rules of tables 59, 65, 68 (io_objects.cpp); a
// configuration the classes refuse all the same keeps their previous one.
void Escon2Io::configure_digital_inputs() {
    DigitalInputConfiguration config;
    for (unsigned input = 1; input <= kDigitalInputCount; ++input) {
        config.functions[input - 1] =
            input_function_from_code(
                od_.get_as<std::uint8_t>(0x3142, static_cast<std::uint8_t>(input)))
                .value_or(InputFunction::None);
    }
    config.polarity = od_.get_as<std::uint16_t>(0x3141, 2);
    config.sensor2_configured = (od_.get_as<std::uint32_t>(0x3000, 1) & 0xFF00) == kSensor2Encoder;
    (void)digital_inputs_.configure(config);
}

void Escon2Io::configure_analog_inputs() {
    AnalogInputConfiguration config;
    for (unsigned n = 1; n <= kAnalogInputCount; ++n) {
        config.functions[n - 1] =
            analog_input_function_from_code(
                od_.get_as<std::uint8_t>(0x3161, static_cast<std::uint8_t>(n)))
                .value_or(AnalogInputFunction::None);
        config.adjustments[n - 1] = {
            .offset =
                od_.get_as<std::int32_t>(0x3163, static_cast<std::uint8_t>(2 * n - 1)) / 1000.0,
            .gain = od_.get_as<std::uint16_t>(0x3163, static_cast<std::uint8_t>(2 * n)) / 10'000.0};
    }
    (void)analog_inputs_.configure(config, digital_inputs_.configuration());
}

void Escon2Io::configure_digital_outputs() {
    DigitalOutputConfiguration config;
    for (unsigned output = 1; output <= kDigitalOutputCount; ++output) {
        config.functions[output - 1] =
            output_function_from_code(
                od_.get_as<std::uint8_t>(0x3151, static_cast<std::uint8_t>(output)))
                .value_or(OutputFunction::None);
    }
    config.polarity = od_.get_as<std::uint16_t>(0x3150, 2);
    const std::uint32_t sensors = od_.get_as<std::uint32_t>(0x3000, 1);
    config.hall_sensor_present = (sensors & 0xFF) == kSensor1Hall;
    config.sensor2_configured = (sensors & 0xFF00) == kSensor2Encoder;
    (void)digital_outputs_.configure(config);
    digital_outputs_.write_general_purpose(od_.get_as<std::uint32_t>(0x3152, 0));
}

// 6.2.52 - 6.2.54: velocity units, mA, 0.1 °C in; mV out.
void Escon2Io::configure_analog_outputs() {
    AnalogOutputConfiguration config;
    for (unsigned n = 1; n <= kAnalogOutputCount; ++n) {
        config.functions[n - 1] =
            analog_output_function_from_code(
                od_.get_as<std::uint8_t>(0x3171, static_cast<std::uint8_t>(n)))
                .value_or(AnalogOutputFunction::None);
    }
    const auto line = [this](std::uint16_t index, std::uint8_t first, double unit) {
        const auto at = [&](std::uint8_t sub) {
            return static_cast<double>(od_.get_as<std::int32_t>(index, sub));
        };
        return TwoPointScaling{.first_input = at(first) * unit,
                               .first_value = at(first + 1) / 1000.0,
                               .second_input = at(first + 2) * unit,
                               .second_value = at(first + 3) / 1000.0};
    };
    config.scalings.velocity = line(0x31C1, 1, 1.0);
    config.scalings.current = line(0x31C2, 1, 1e-3);
    config.scalings.logic_section_temperature = line(0x31C3, 1, 0.1);
    config.scalings.power_stage_temperature = line(0x31C3, 5, 0.1);
    analog_outputs_.configure(config);
    analog_outputs_.write_general_purpose(AnalogOutputFunction::GeneralPurposeA,
                                          od_.get_as<std::int16_t>(0x3172, 1) / 1000.0);
    analog_outputs_.write_general_purpose(AnalogOutputFunction::GeneralPurposeB,
                                          od_.get_as<std::int16_t>(0x3172, 2) / 1000.0);
}

void Escon2Io::watch() {
    const auto on = [this](std::initializer_list<std::uint16_t> indices, auto configure) {
        for (const std::uint16_t index : indices) {
            od_.on_change(index,
                          [this, configure](std::uint16_t, std::uint8_t) { (this->*configure)(); });
        }
    };
    on({0x3141, 0x3142, 0x3000}, &Escon2Io::configure_digital_inputs);
    on({0x3161, 0x3163, 0x3142}, &Escon2Io::configure_analog_inputs);
    on({0x3150, 0x3151, 0x3000}, &Escon2Io::configure_digital_outputs);
    on({0x3171, 0x3172, 0x31C1, 0x31C2, 0x31C3}, &Escon2Io::configure_analog_outputs);
    // 6.2.35, 6.2.78: the host writes the general purpose outputs through either object.
    for (const std::uint16_t index : {std::uint16_t{0x3152}, std::uint16_t{0x60FE}}) {
        od_.on_change(index, [this, index](std::uint16_t, std::uint8_t sub) {
            if (!storing_) {
                digital_outputs_.write_general_purpose(od_.get_as<std::uint32_t>(index, sub));
            }
        });
    }
}

void Escon2Io::set_digital_input(unsigned input, bool high, double now) {
    digital_inputs_.set_level(input, high, now);
    if (input <= pwm_inputs_.size() && !pwm_signals_[input - 1]) {
        pwm_inputs_[input - 1].set_level(high, now);
    }
}

bool Escon2Io::digital_input(unsigned input) const {
    return (od_.get_as<std::uint16_t>(0x3141, 1) >> (input - 1) & 1U) != 0;
}

void Escon2Io::set_pwm_signal(unsigned input, std::optional<PwmSignal> signal) {
    pwm_signals_.at(input - 1) = signal;
}

void Escon2Io::set_analog_input(unsigned input, double volts) {
    analog_inputs_.set_voltage(input, volts);
}

// The duty cycle (%) of the PWM input carrying `function`, if one does and measures.
std::optional<double> Escon2Io::pwm_duty_cycle(InputFunction function) const {
    const std::optional<unsigned> input = digital_inputs_.input_of(function);
    if (!input || *input > pwm_inputs_.size() || pwm_inputs_[*input - 1].error()) {
        return std::nullopt;
    }
    return pwm_inputs_[*input - 1].duty_cycle();
}

// A two-point scaling object (6.2.44 - 6.2.51) with its inputs and values in SI-like units.
TwoPointScaling Escon2Io::scaling(std::uint16_t index, double input_unit, double value_unit) const {
    const auto at = [this, index](std::uint8_t sub) {
        return static_cast<double>(od_.get_as<std::int32_t>(index, sub));
    };
    return {.first_input = at(1) * input_unit,
            .first_value = at(2) * value_unit,
            .second_input = at(3) * input_unit,
            .second_value = at(4) * value_unit};
}

// Tables 59, 61, 62, 68: a set value (or offset) from the PWM input, the set value switches or
// the analog input that carries its function, in velocity units or mA; direction [d] turns the
// set value, not the offset.
std::optional<double> Escon2Io::set_value(bool velocity, bool offset, double now) {
    const InputFunction pwm = velocity ? (offset ? InputFunction::PwmVelocitySetValueOffset
                                                 : InputFunction::PwmVelocitySetValue)
                                       : (offset ? InputFunction::PwmCurrentSetValueOffset
                                                 : InputFunction::PwmCurrentSetValue);
    const AnalogInputFunction analog = velocity
                                           ? (offset ? AnalogInputFunction::VelocitySetValueOffset
                                                     : AnalogInputFunction::VelocitySetValue)
                                           : (offset ? AnalogInputFunction::CurrentSetValueOffset
                                                     : AnalogInputFunction::CurrentSetValue);
    const std::uint16_t pwm_scaling =
        velocity ? (offset ? 0x3181 : 0x3180) : (offset ? 0x3185 : 0x3184);
    const std::uint16_t analog_scaling =
        velocity ? (offset ? 0x31B1 : 0x31B0) : (offset ? 0x31B5 : 0x31B4);
    std::optional<double> value;
    if (const auto duty = pwm_duty_cycle(pwm)) {
        value = scaling(pwm_scaling, 0.1, 1.0).apply(*duty); // duty cycles in 0.1 %
    } else if (const auto volts = analog_inputs_.voltage_for(analog)) {
        value = scaling(analog_scaling, 1e-3, 1.0).apply(*volts); // voltages in mV
    } else if (!offset) {
        const auto selected = digital_inputs_.selected_set_value(
            velocity ? SetValueSwitch::Velocity : SetValueSwitch::Current, now);
        if (selected) {
            value = od_.get_as<std::int32_t>(velocity ? 0x3146 : 0x3147,
                                             static_cast<std::uint8_t>(*selected + 1));
        }
    }
    if (value && !offset && digital_inputs_.input_of(InputFunction::Direction)) {
        value = apply_direction(*value, digital_inputs_.active(InputFunction::Direction, now));
    }
    return value;
}

IoReaction Escon2Io::read_inputs(double period_start, double now, bool velocity_mode) {
    IoReaction reaction;
    for (unsigned input = 1; input <= pwm_inputs_.size(); ++input) {
        PwmInput& pwm = pwm_inputs_[input - 1];
        if (pwm_signals_[input - 1]) {
            pwm_signals_[input - 1]->drive(pwm, period_start, now);
        }
        pwm.update(now);
        const InputFunction carried = digital_inputs_.configuration().functions[input - 1];
        const std::vector<DeviceErrorCode> conditions = pwm.conditions();
        if (is_pwm_function(carried)) {
            reaction.conditions.insert(reaction.conditions.end(), conditions.begin(),
                                       conditions.end());
        }
        for (const DeviceErrorCode warning :
             {input == 1 ? DeviceErrorCode::DigitalInput1PwmFrequencyWarning
                         : DeviceErrorCode::DigitalInput2PwmFrequencyWarning,
              input == 1 ? DeviceErrorCode::DigitalInput1PwmDutyCycleWarning
                         : DeviceErrorCode::DigitalInput2PwmDutyCycleWarning}) {
            if (!is_pwm_function(carried) ||
                std::ranges::find(conditions, warning) == conditions.end()) {
                reaction.cleared.push_back(warning);
            }
        }
        store(0x314B, static_cast<std::uint8_t>(input), pwm.frequency_object());
        store(0x314C, static_cast<std::uint8_t>(input), pwm.duty_cycle_object());
    }
    if (const auto limit = digital_inputs_.limit_switch_error(now)) {
        reaction.conditions.push_back(*limit);
    }
    const bool drive_enable = digital_inputs_.active(InputFunction::DriveEnable, now);
    if (drive_enable != drive_enable_) {
        drive_enable_ = drive_enable;
        reaction.drive_enable = drive_enable;
    }
    const bool quick_stop = digital_inputs_.active(InputFunction::QuickStop, now);
    if (quick_stop != quick_stop_) {
        quick_stop_ = quick_stop;
        reaction.quick_stop = quick_stop;
    }
    const auto as_object = [](std::optional<double> value) {
        return value ? std::optional<std::int32_t>(rounded(*value)) : std::nullopt;
    };
    if (velocity_mode) {
        reaction.set_values.velocity = as_object(set_value(true, false, now));
        reaction.set_values.velocity_offset = as_object(set_value(true, true, now));
    } else {
        reaction.set_values.current = as_object(set_value(false, false, now));
        reaction.set_values.current_offset = as_object(set_value(false, true, now));
    }
    // 6.2.26, 6.2.28, 6.2.77, 6.2.36, 6.2.38, 6.2.40
    store(0x3141, 1, digital_inputs_.logic_state(now));
    store(0x3143, 0, digital_inputs_.functionality(now));
    store(0x60FD, 0, digital_inputs_.cia_inputs(now));
    for (unsigned n = 1; n <= kAnalogInputCount; ++n) {
        const auto sub = static_cast<std::uint8_t>(n);
        store(0x3160, sub, millivolts(analog_inputs_.voltage(n)));
        store(0x3164, sub, analog_inputs_.raw_value(n));
    }
    store(0x3162, 1,
          millivolts(analog_inputs_.general_purpose(AnalogInputFunction::GeneralPurposeA)));
    store(0x3162, 2,
          millivolts(analog_inputs_.general_purpose(AnalogInputFunction::GeneralPurposeB)));
    return reaction;
}

void Escon2Io::write_outputs(const IoState& state, double dt) {
    digital_outputs_.set_device_state(state.fault, state.limiting);
    digital_outputs_.step(state.velocity_rpm, state.pole_pairs, dt);
    analog_outputs_.update(state.monitored);
    storing_ = true;
    store(0x3152, 0, digital_outputs_.functionality());
    store(0x60FE, 1, digital_outputs_.cia_outputs());
    storing_ = false;
    store(0x3150, 1, digital_outputs_.logic_state());
    for (unsigned n = 1; n <= kAnalogOutputCount; ++n) {
        store(0x3170, static_cast<std::uint8_t>(n), millivolts(analog_outputs_.voltage(n)));
    }
}

template <typename T>
void Escon2Io::store(std::uint16_t index, std::uint8_t sub, T value) {
    if (od_.get_as<T>(index, sub) != value) {
        od_.set_as(index, sub, value);
    }
}

} // namespace eposp::drives::escon2
