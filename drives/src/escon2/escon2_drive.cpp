#include "eposp/drives/escon2/escon2_drive.hpp"

#include "axis_configuration.hpp"
#include "eposp/drives/escon2/units.hpp"
#include "eposp/drives/motion/profile_planner.hpp"
#include "eposp/drives/motion/statusword_bits.hpp"
#include "escon2_io.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace eposp::drives::escon2 {
namespace {

using motion::DriveState;

// Table 18 / 24: statusword bit 12 "drive follows command value" (bit 11 is motion's).
constexpr std::uint16_t kFollowsCommandValueBit = 1U << 12;
constexpr std::uint16_t kFaultResetBit = 1U << 7; // table 98
// Table 8: the device commands the drive enable and quick stop inputs give.
constexpr std::uint16_t kDeviceCommandBits = 0x008F;
constexpr std::uint16_t kDisableVoltage = 0x0000;
constexpr std::uint16_t kQuickStop = 0x0002;
constexpr std::uint16_t kShutdown = 0x0006;
constexpr std::uint16_t kEnableOperation = 0x000F;

// Table 49: the control structures with a velocity controller and their main sensor.
constexpr std::uint32_t kCurrentControlOnly = 0x0000'0001;
constexpr std::uint32_t kMainSensorSensor1 = 0x0001'0011;
constexpr std::uint32_t kMainSensorSensor2 = 0x0002'0011;
// Table 47: sensor 1 the digital Hall sensor, sensor 2 the digital incremental encoder.
constexpr std::uint32_t kSensor1Mask = 0x00FF;
constexpr std::uint32_t kSensor2Mask = 0xFF00;
// Table 52: the supervision switches of 0x3000 sub 4.
constexpr std::uint32_t kMainSensorSupervisionDisabled = 1U << 8;
constexpr std::uint32_t kCommutationSensorSupervisionDisabled = 1U << 9;

// Table 110: the errors the drive itself detects.
constexpr std::uint16_t kOvercurrentError = 0x2310;              // 7.1.3
constexpr std::uint16_t kPowerStageProtectionError = 0x2320;     // 7.1.4
constexpr std::uint16_t kLoadingParameterFailedError = 0x6380;   // 7.1.17
constexpr std::uint16_t kCurrentOffsetWarning = 0x7280;          // 7.1.21
constexpr std::uint16_t kMissingMainSensorError = 0x7390;        // 7.1.25
constexpr std::uint16_t kMissingCommutationSensorError = 0x7391; // 7.1.26
constexpr std::uint16_t kMainSensorDirectionError = 0x7392;      // 7.1.27
constexpr std::uint16_t kModeNotSupportedError = 0xFF0D;         // 7.1.41
// 7.1.22 - 7.1.24: the sensor supervision's errors. A Hall sensor 3 edge missing for a turn is
// a Hall signal error (7.1.23: "incorrect wiring of Hall sensor supply voltage"); the encoder
// has no index (6.2.16.2), so its index checks never run: a main sensor breach if they did.
constexpr motion::SensorErrorCodes kSensorErrorCodes{.encoder_breach = 0x7380,
                                                     .index_not_found = 0x7380,
                                                     .encoder_resolution = 0x7380,
                                                     .hall_sensor_not_found = 0x7388,
                                                     .hall_signal = 0x7388,
                                                     .hall_angle = 0x738A};

std::int16_t deci_celsius(double celsius) {
    return static_cast<std::int16_t>(std::clamp(std::round(celsius * 10), -32768.0, 32767.0));
}

motion::FaultClass fault_class(FaultReactionCode reaction) {
    // 7.1: "f" quick stop ramp (the CiA 402 fault reaction option code 2 of DeviceControl's
    // defaults), "d" disables at once.
    return reaction == FaultReactionCode::QuickStop ? motion::FaultClass::Device
                                                    : motion::FaultClass::Critical;
}

std::int32_t rounded(double value) {
    using Limits = std::numeric_limits<std::int32_t>;
    return static_cast<std::int32_t>(
        std::clamp(std::round(value), double{Limits::min()}, double{Limits::max()}));
}

} // namespace

Escon2Drive::Escon2Drive(core::EventLoop& loop, Escon2DriveConfig config)
    : loop_(loop), dictionary_(with_power_disable_rule(std::move(config.dictionary), *this)),
      machine_(config.axis), axis_(config.axis),
      device_control_(motion::OptionCodes{}, motion::StateMachine::Escon2),
      errors_(dictionary_.objects()), power_stage_(config.power_stage_thermal),
      power_stage_loss_resistance_(config.power_stage_loss_resistance),
      ambient_temperature_(config.power_stage_thermal.ambient_temperature),
      control_time_(loop.now() + kControlPeriod),
      control_timer_(loop,
                     loop.every(kControlPeriod, control_time_, [this] { control_period(); })) {
    write_axis_defaults(dictionary_.objects(), machine_);
    configure_axis();
    read_sensor_configuration();
    const HardwareData& hardware = dictionary_.hardware();
    const auto volts = [](std::int64_t millivolts) {
        return static_cast<double>(millivolts) / 1000.0;
    };
    io_ = std::make_unique<Escon2Io>(
        dictionary_.objects(), volts(hardware.analog_input_low), volts(hardware.analog_input_high),
        volts(hardware.analog_output_low), volts(hardware.analog_output_high), seconds());
    watch_dictionary();
    compute_measured_values();
    set_supply_voltage(machine_.plant.power_stage.supply_voltage);
}

Escon2Drive::~Escon2Drive() = default;

// «Power Disable»: the power stage is off and no fault is pending (6.2.6, 6.2.13 …).
Escon2DictionaryConfig Escon2Drive::with_power_disable_rule(Escon2DictionaryConfig config,
                                                            const Escon2Drive& drive) {
    config.power_disabled = [&drive] {
        return drive.power_disabled();
    };
    return config;
}

bool Escon2Drive::power_disabled() const {
    const DriveState state = device_control_.state();
    return state == DriveState::Start || state == DriveState::NotReadyToSwitchOn ||
           state == DriveState::SwitchOnDisabled || state == DriveState::ReadyToSwitchOn;
}

void Escon2Drive::start() {
    const canopen::StoredValuesReport stored = dictionary_.power_up();
    configure_axis(); // the power-up restored values without telling the listeners
    read_sensor_configuration();
    io_->reload();
    errors_.reset();
    system_load_.restart();
    device_control_.node_reset();
    device_control_.initialise();              // 0
    device_control_.initialisation_finished(); // 1
    controlword_ = 0;
    power_stage_on_ = false;
    stop_.reset();
    on_mode_written();
    if (stored.refused()) {
        raise_device_error(kLoadingParameterFailedError); // 7.1.17: the defaults are set
    }
    publish();
}

void Escon2Drive::set_velocity_set_value(std::int32_t velocity) {
    objects().set_as(0x60FF, 0, velocity);
}

void Escon2Drive::set_velocity_offset(std::int32_t velocity) {
    objects().set_as(0x60B1, 0, velocity);
}

void Escon2Drive::set_current_set_value(std::int32_t milliamperes) {
    objects().set_as(0x30F0, 0, milliamperes);
}

void Escon2Drive::set_current_offset(std::int32_t milliamperes) {
    objects().set_as(0x30F1, 0, milliamperes);
}

void Escon2Drive::set_digital_input(unsigned input, bool high) {
    io_->set_digital_input(input, high,
                           std::chrono::duration<double>(loop_.now().time_since_epoch()).count());
}

bool Escon2Drive::digital_input(unsigned input) const {
    return io_->digital_input(input);
}

void Escon2Drive::set_pwm_signal(unsigned input, std::optional<PwmSignal> signal) {
    io_->set_pwm_signal(input, signal);
}

void Escon2Drive::set_analog_input(unsigned input, double volts) {
    io_->set_analog_input(input, volts);
}

bool Escon2Drive::digital_output(unsigned output) const {
    return io_->digital_output(output);
}

double Escon2Drive::analog_output(unsigned output) const {
    return io_->analog_output(output);
}

void Escon2Drive::set_supply_voltage(double volts) {
    machine_.plant.power_stage.supply_voltage = volts;
    configure_axis();
    supply_.update(volts, false);
    objects().set_as(0x2200, 1, supply_.voltage_object()); // 0.1 V
}

void Escon2Drive::raise_device_error(std::uint16_t code) {
    const DeviceError& error = device_error(code);
    if (errors_.raise(code) && error.reaction != FaultReactionCode::Warning) {
        device_control_.fault_occurred(fault_class(error.reaction));
    }
    update_fault_condition();
    publish();
}

// 7.1.6 - 7.1.10: a fault reset is refused while the supply or a temperature is still out of
// range, and while an error needs a device reset.
void Escon2Drive::update_fault_condition() {
    device_control_.set_fault_condition_present(
        errors_.needs_device_reset() || supply_.undervoltage() || supply_.overvoltage() ||
        thermal_.power_stage_error() || thermal_.logic_section_error() ||
        system_load_.peak_overloaded());
}

// 6.2.10 - 6.2.12, 6.2.56, 7.1.36 - 7.1.40: the supply, the temperatures and the system
// load, every control period.
void Escon2Drive::supervise() {
    if (system_load_.update()) {
        watchdog_reset();
        return;
    }
    const DriveState state = device_control_.state();
    supply_.update(machine_.plant.power_stage.supply_voltage,
                   state == DriveState::OperationEnable || state == DriveState::QuickStopActive);
    thermal_.update(power_stage_.temperature(), logic_section_temperature());
    std::vector<DeviceErrorCode> conditions = supply_.conditions();
    for (const auto& more : {thermal_.conditions(), system_load_.conditions()}) {
        conditions.insert(conditions.end(), more.begin(), more.end());
    }
    for (const DeviceErrorCode condition : conditions) {
        raise_device_error(static_cast<std::uint16_t>(condition));
    }
    // 7.1.9: the warning clears itself below the warning temperature.
    constexpr auto kWarning =
        static_cast<std::uint16_t>(DeviceErrorCode::ThermalPowerStageOverloadWarning);
    if (!thermal_.power_stage_warning() && errors_.active(kWarning)) {
        clear_warning(kWarning);
    }
    update_fault_condition();
}

// 7.1.37: the device starts again as at power-up (what was not stored is lost) and says why.
void Escon2Drive::watchdog_reset() {
    start();
    raise_device_error(static_cast<std::uint16_t>(DeviceErrorCode::Watchdog));
}

void Escon2Drive::watch_sensors() {
    if (const auto fault = sensor_supervision_.update(axis_.motor().state().angle,
                                                      axis_.hall_sensors(), sensor_faults_)) {
        raise_device_error(kSensorErrorCodes.of(*fault));
    }
    // 7.1.27: the motor's turning shows at its terminals only with the power stage on.
    const bool watching = power_stage_on_ && direction_supervision_;
    if (sensor_direction_.update(watching ? axis_.motor().state().speed : 0,
                                 axis_.position_actual())) {
        raise_device_error(kMainSensorDirectionError);
    }
}

// 6.2.13, 6.2.14.3, 6.2.16: what the sensor supervision checks; a new configuration is a
// start-up. The breach is the main sensor's (7.1.22), so the encoder's only as main sensor; the
// Hall checks are the commutation sensor's (7.1.23, 7.1.24: the angle against the encoder's).
void Escon2Drive::read_sensor_configuration() {
    const auto& od = objects();
    const std::uint32_t sensors = od.get_as<std::uint32_t>(0x3000, 1);
    const std::uint32_t miscellaneous = od.get_as<std::uint32_t>(0x3000, 4);
    const bool encoder = (sensors & kSensor2Mask) != 0;
    const bool hall_sensors = (sensors & kSensor1Mask) != 0 &&
                              (miscellaneous & kCommutationSensorSupervisionDisabled) == 0;
    const bool main_sensor_supervised = od.get_as<std::uint32_t>(0x3000, 2) == kMainSensorSensor2 &&
                                        (miscellaneous & kMainSensorSupervisionDisabled) == 0;
    sensor_supervision_.configure(
        {.encoder_pulses = static_cast<int>(od.get_as<std::uint32_t>(0x3010, 1)),
         .encoder = encoder,
         .encoder_index = false,
         .hall_sensors = hall_sensors,
         .breach_supervision = main_sensor_supervised,
         .hall_angle = hall_sensors && encoder,
         .pole_pairs = od.get_as<std::uint8_t>(0x3001, 3)});
    // 7.1.27 is the main sensor supervision's too (table 52 bit 8); a quarter turn of the
    // encoder against the motor is the error (the manual gives no threshold).
    direction_supervision_ = main_sensor_supervised;
    sensor_direction_ = motion::SensorDirectionMonitor(od.get_as<std::uint32_t>(0x3010, 1),
                                                       axis_.position_actual());
    restart_sensor_supervision();
}

void Escon2Drive::restart_sensor_supervision() {
    sensor_supervision_.restart(axis_.motor().state().angle, axis_.hall_sensors(), sensor_faults_);
}

double Escon2Drive::logic_section_temperature() const {
    return ambient_temperature_; // the logic dissipates too little to matter here
}

void Escon2Drive::set_ambient_temperature(double celsius) {
    ambient_temperature_ = celsius;
    plant::ThermalParameters parameters = power_stage_.parameters();
    parameters.ambient_temperature = celsius;
    power_stage_.set_parameters(parameters);
}

void Escon2Drive::clear_warning(std::uint16_t code) {
    errors_.clear_warning(code);
}

void Escon2Drive::configure_axis() {
    const auto& od = objects();
    machine_.plant.power_stage.max_duty = max_duty_cycle(); // table 97
    axis_.reconfigure(configured_axis(od, machine_));
    const HardwareData& hardware = dictionary_.hardware();
    CurrentLimitationParameters limits;
    limits.motor = {.continuous_current = od.get_as<std::uint32_t>(0x3001, 1) / 1000.0,
                    .output_current_limit = od.get_as<std::uint32_t>(0x3001, 2) / 1000.0,
                    .time_constant = od.get_as<std::uint16_t>(0x3001, 4) / 10.0,
                    .release_level = CurrentLimitationParameters::kReleaseLevel};
    // 6.2.56 note: the Nano 24/2 limits by temperature only. The power stage's rating is that
    // of its hardware (tables 53, 54).
    if (hardware.hardware_version == hardware_data(Escon2Hardware::Nano24_2).hardware_version) {
        limits.power_stage.reset();
    } else {
        limits.power_stage = motion::I2tParameters{
            .continuous_current = static_cast<double>(hardware.nominal_current.max) / 1000.0,
            .output_current_limit = static_cast<double>(hardware.output_current_limit.max) / 1000.0,
            .time_constant = limits.power_stage->time_constant,
            .release_level = CurrentLimitationParameters::kReleaseLevel};
    }
    limits.max_power_stage_temperature = od.get_as<std::uint16_t>(0x3201, 3) / 10.0;
    limitation_.set_parameters(limits);
    // Tables 41 - 46: 0x2201 in mV, the hardware's hystereses and logic section limit.
    (void)supply_.set_limits(
        {.undervoltage_limit = od.get_as<std::uint32_t>(0x2201, 1) / 1000.0,
         .undervoltage_hysteresis = static_cast<double>(hardware.undervoltage_hysteresis) / 1000.0,
         .overvoltage_limit = od.get_as<std::uint32_t>(0x2201, 2) / 1000.0,
         .overvoltage_hysteresis = static_cast<double>(hardware.overvoltage_hysteresis) / 1000.0});
    thermal_.set_limits(
        {.max_power_stage_temperature = limits.max_power_stage_temperature,
         .logic_section_limit = static_cast<double>(hardware.logic_temperature_limit) / 10.0,
         .logic_section_hysteresis =
             static_cast<double>(hardware.logic_temperature_hysteresis) / 10.0});
}

void Escon2Drive::watch_dictionary() {
    auto& od = objects();
    od.on_change(0x6040, [this](std::uint16_t, std::uint8_t) {
        on_controlword(objects().get_as<std::uint16_t>(0x6040, 0));
    });
    od.on_change(0x6060, [this](std::uint16_t, std::uint8_t) { on_mode_written(); });
    for (const std::uint16_t index : kAxisConfigurationObjects) {
        od.on_change(index, [this](std::uint16_t, std::uint8_t) { configure_axis(); });
    }
    for (const std::uint16_t index : {std::uint16_t{0x2201}, std::uint16_t{0x3201}}) {
        od.on_change(index, [this](std::uint16_t, std::uint8_t) { configure_axis(); });
    }
    // The sensors, and of 0x3001 only the pole pairs: its currents change while running.
    for (const std::uint16_t index : {std::uint16_t{0x3000}, std::uint16_t{0x3001},
                                      std::uint16_t{0x3010}, std::uint16_t{0x6402}}) {
        od.on_change(index, [this](std::uint16_t changed, std::uint8_t sub) {
            if (changed != 0x3001 || sub == 3) {
                read_sensor_configuration();
            }
        });
    }
    // 6.2.13.1: a brushed motor has no Hall sensor.
    od.on_change(0x6402, [this](std::uint16_t, std::uint8_t) {
        if (objects().get_as<std::uint16_t>(0x6402, 0) == 1) {
            objects().set_as(0x3000, 1, objects().get_as<std::uint32_t>(0x3000, 1) & ~0xFFU);
        }
    });
}

// Measured values computed when read (the USB host reads them now and then).
void Escon2Drive::compute_measured_values() {
    auto& od = objects();
    const auto computed = [&od](std::uint16_t index, std::uint8_t sub, auto read) {
        od.find(index, sub)->on_read = [read] {
            return canopen::encode(read());
        };
    };
    computed(0x30D1, 1, [this] {
        return rounded(polarity() * current_averaged_.output() * 1000); // 6.2.21.1
    });
    computed(0x30D3, 1, [this] { // 6.2.23.1
        return rounded(to_velocity_units(polarity() * velocity_averaged_.output()));
    });
    // 6.2.76: each sensor's velocity, 0 where none is configured. Both sit on the motor shaft.
    const auto sensor_velocity = [this](std::uint32_t mask, bool averaged) {
        if ((objects().get_as<std::uint32_t>(0x3000, 1) & mask) == 0) {
            return std::int32_t{0};
        }
        const double velocity = averaged ? velocity_averaged_.output() : axis_.velocity_actual();
        return rounded(to_velocity_units(polarity() * velocity));
    };
    computed(0x60E5, 1, [sensor_velocity] { return sensor_velocity(0x00FF, false); });
    computed(0x60E5, 2, [sensor_velocity] { return sensor_velocity(0xFF00, false); });
    computed(0x60E5, 9, [sensor_velocity] { return sensor_velocity(0x00FF, true); });
    computed(0x60E5, 10, [sensor_velocity] { return sensor_velocity(0xFF00, true); });
    // 6.2.22.1, 6.2.66: per thousand of 0x6076 = nominal current × torque constant, so the
    // current in per thousand of the nominal current.
    const auto torque = [this](double amperes) {
        const double nominal = objects().get_as<std::uint32_t>(0x3001, 1) / 1000.0;
        return static_cast<std::int16_t>(
            std::clamp(nominal > 0 ? std::round(polarity() * amperes / nominal * 1000) : 0.0,
                       -32768.0, 32767.0));
    };
    computed(0x6077, 0, [this, torque] { return torque(axis_.current_actual()); });
    computed(0x30D2, 1, [this, torque] { return torque(current_averaged_.output()); });
    computed(0x301A, 2, [this] { // 6.2.17.2
        return std::uint16_t{plant::hall_inputs(axis_.hall_sensors(), sensor_faults_)};
    });
    computed(0x3000, 5, [this] { // 6.2.13.5: increments per turn of the main sensor
        const std::uint32_t structure = objects().get_as<std::uint32_t>(0x3000, 2);
        if (structure == kMainSensorSensor2) {
            return 4 * objects().get_as<std::uint32_t>(0x3010, 1);
        }
        return structure == kMainSensorSensor1
                   ? std::uint32_t{6} * objects().get_as<std::uint8_t>(0x3001, 3)
                   : std::uint32_t{0};
    });
    const auto percent = [](double level) {
        return static_cast<std::uint16_t>(std::clamp(std::round(level * 100), 0.0, 65'535.0));
    };
    computed(0x3200, 1, [this, percent] { return percent(limitation_.motor_level()); });
    computed(0x3201, 1, [this, percent] { return percent(limitation_.power_stage_level()); });
    computed(0x3201, 2, [this] { return deci_celsius(power_stage_.temperature()); });
    computed(0x2202, 1, [this] { return deci_celsius(logic_section_temperature()); });
    // 6.2.57.1: the bridge voltage R·I + k·ω over the supply, 0.1 %.
    computed(0x3203, 1,
             [this] { return static_cast<std::uint16_t>(std::round(pwm_duty_cycle() * 1000)); });
}

// 6.2.57.1: the bridge voltage R·I + k·ω over the supply, at most the PWM max duty cycle of
// table 97 (the plant's power stage saturates there).
double Escon2Drive::pwm_duty_cycle() const {
    const plant::MotorModel& motor = axis_.motor();
    const plant::MotorParameters& data = motor.parameters().motor;
    const double volts = data.terminal_resistance * motor.state().current +
                         data.back_emf_constant() * motor.state().speed;
    const double supply = machine_.plant.power_stage.supply_voltage;
    const double duty = supply > 0 && power_stage_on_ ? std::abs(volts) / supply : 0.0;
    return std::min(duty, max_duty_cycle());
}

double Escon2Drive::max_duty_cycle() const {
    return static_cast<double>(dictionary_.hardware().pwm_max_duty_cycle) / 1000.0;
}

// Table 8: the device commands, fault reset and clear warning on bit 7's rising edge.
void Escon2Drive::on_controlword(std::uint16_t controlword) {
    const bool reset_edge =
        (controlword & kFaultResetBit) != 0 && (controlword_ & kFaultResetBit) == 0;
    controlword_ = controlword;
    const DriveState before = device_control_.state();
    if (reset_edge) {
        errors_.clear_warnings();
        update_fault_condition();
    }
    device_control_.write_controlword(controlword);
    // Transition 15 only "if no fault is present" (a cause still there, a device reset needed).
    if (before == DriveState::Fault && device_control_.state() != DriveState::Fault) {
        errors_.fault_reset();
        restart_sensor_supervision(); // a sensor fault still there is found again
    }
    if (before != DriveState::OperationEnable &&
        device_control_.state() == DriveState::OperationEnable) {
        check_configuration();
    }
    publish();
}

// 7.1.25, 7.1.26, 7.1.41: what the enabled drive needs of its configuration.
void Escon2Drive::check_configuration() {
    const auto& od = objects();
    const std::uint32_t sensors = od.get_as<std::uint32_t>(0x3000, 1);
    const std::uint32_t structure = od.get_as<std::uint32_t>(0x3000, 2);
    const bool sensor1 = (sensors & 0x00FF) != 0;
    const bool sensor2 = (sensors & 0xFF00) != 0;
    if ((structure == kMainSensorSensor1 && !sensor1) ||
        (structure == kMainSensorSensor2 && !sensor2)) {
        raise_device_error(kMissingMainSensorError);
    }
    const std::uint32_t commutation = od.get_as<std::uint32_t>(0x3000, 3);
    const bool brushless = od.get_as<std::uint16_t>(0x6402, 0) == 10;
    if (brushless && (commutation == 0 || ((commutation & 0xF0) != 0 && !sensor1) ||
                      ((commutation & 0x0F) != 0 && !sensor2))) {
        raise_device_error(kMissingCommutationSensorError);
    }
    // 3.3: the velocity mode runs on the velocity controller, which needs a main sensor.
    if (mode_ == OperatingMode::IoVelocity && structure == kCurrentControlOnly) {
        raise_device_error(kModeNotSupportedError);
    }
}

// 6.2.62: the display follows; the mode starts from the actual state.
void Escon2Drive::on_mode_written() {
    const auto written = objects().get_as<std::int8_t>(0x6060, 0);
    mode_ = static_cast<OperatingMode>(written);
    objects().set_as(0x6061, 0, written);
    demand_ = {static_cast<double>(axis_.position_actual()), axis_.velocity_actual(), 0};
    ramp_ = motion::Trajectory(demand_.position, {});
    ramp_start_ = seconds();
    ramp_target_ = std::numeric_limits<double>::quiet_NaN(); // replanned at the next period
    if (device_control_.state() == DriveState::OperationEnable) {
        check_configuration();
    }
}

// One millisecond: the device control's outputs, the mode's demand, ten steps of the current
// loop and the plant with the current limitation, the computed objects. It runs at
// control_time_, the timer's scheduled time, never at the loop's now().
void Escon2Drive::control_period() {
    const double now = seconds();
    react_to_inputs(io_->read_inputs(now - plant::ServoAxis::kOuterLoopPeriod, now,
                                     mode_ == OperatingMode::IoVelocity));
    if ((device_control_.state() == DriveState::FaultReactionActiveDisabled ||
         device_control_.state() == DriveState::FaultReactionActiveEnabled) &&
        device_control_.outputs().ramp == motion::StopRamp::None) {
        device_control_.stop_completed(); // 14: nothing to ramp down
    }
    follow_power_stage();
    const motion::DriveOutputs outputs = device_control_.outputs();
    plant::ControlMode loop = plant::ControlMode::PowerOff;
    plant::AxisDemand demand;
    set_value_limited_ = false;
    if (power_stage_on_ && outputs.ramp != motion::StopRamp::None) {
        loop = plant::ControlMode::Velocity;
        demand = stop_ramp(now);
    } else if (power_stage_on_ && outputs.drive_function_enabled) {
        if (stop_) { // transition 16: the mode starts over from rest
            stop_.reset();
            on_mode_written();
        }
        const bool velocity = mode_ == OperatingMode::IoVelocity;
        loop = velocity ? plant::ControlMode::Velocity : plant::ControlMode::Current;
        demand = velocity ? velocity_mode(now) : current_mode();
    }
    axis_.set_mode(loop);
    axis_.set_demand(demand);
    const double overcurrent = machine_.plant.power_stage.overcurrent;
    bool overcurrent_seen = false;
    for (int step = 0; step < plant::ServoAxis::kCurrentStepsPerOuterLoop; ++step) {
        axis_.step();
        current_averaged_.update(axis_.current_actual());
        const double current = axis_.current_actual();
        power_stage_.step(current * current * power_stage_loss_resistance_,
                          plant::ServoAxis::kCurrentLoopPeriod);
        limitation_.update(current, power_stage_.temperature(),
                           plant::ServoAxis::kCurrentLoopPeriod);
        overcurrent_seen = overcurrent_seen || std::abs(axis_.current_actual()) > overcurrent;
    }
    axis_.reduce_current_limit(limitation_.limit()); // 3.6.2
    // 7.1.4: the power stage protection trips on the shorted winding it drives, before the
    // current it would let through is measured. 7.1.5's 0x2380 has the same causes; the manual
    // does not tell them apart, so the model raises 0x2320 only.
    if (winding_shorted_ && power_stage_on_) {
        raise_device_error(kPowerStageProtectionError);
    }
    if (overcurrent_seen) {
        raise_device_error(kOvercurrentError);
    }
    watch_sensors();
    supervise();
    velocity_averaged_.update(axis_.velocity_actual());
    publish();
    const DriveState state = device_control_.state();
    const double counts_to_rpm = 1.0 / counts_per_rpm();
    io_->write_outputs(
        {.fault = state == DriveState::Fault || state == DriveState::FaultReactionActiveDisabled ||
                  state == DriveState::FaultReactionActiveEnabled,
         .limiting = (statusword() & motion::kInternalLimitActiveBit) != 0,
         .monitored = {.velocity = to_velocity_units(polarity() * axis_.velocity_actual()),
                       .velocity_averaged =
                           to_velocity_units(polarity() * velocity_averaged_.output()),
                       .current = polarity() * axis_.current_actual(),
                       .current_averaged = polarity() * current_averaged_.output(),
                       .logic_section_temperature = logic_section_temperature(),
                       .power_stage_temperature = power_stage_.temperature()},
         .velocity_rpm = axis_.velocity_actual() * counts_to_rpm,
         .pole_pairs = objects().get_as<std::uint8_t>(0x3001, 3)},
        plant::ServoAxis::kOuterLoopPeriod);
    control_time_ += kControlPeriod;
}

// Tables 59, 60: the set values the inputs command, drive enable and quick stop as device
// commands, the limit switches while the drive runs (7.1.28, 7.1.29) and the PWM conditions
// (7.1.30 - 7.1.35).
void Escon2Drive::react_to_inputs(const IoReaction& reaction) {
    const InputSetValues& values = reaction.set_values;
    if (values.velocity) {
        set_velocity_set_value(*values.velocity);
    }
    if (values.velocity_offset) {
        set_velocity_offset(*values.velocity_offset);
    }
    if (values.current) {
        set_current_set_value(*values.current);
    }
    if (values.current_offset) {
        set_current_offset(*values.current_offset);
    }
    // "Enable / disable the drive or clear errors in Fault state".
    if (reaction.drive_enable) {
        if (!*reaction.drive_enable) {
            command(kDisableVoltage);
        } else if (device_control_.state() == DriveState::Fault) {
            command(kDisableVoltage);
            command(kFaultResetBit);
        } else {
            command(kShutdown);
            command(kEnableOperation);
        }
    }
    // "Stop movement and switch to «Quick stop active» state"; released, operation resumes (16).
    if (reaction.quick_stop) {
        if (*reaction.quick_stop) {
            command(kQuickStop);
        } else if (device_control_.state() == DriveState::QuickStopActive) {
            command(kEnableOperation);
        }
    }
    for (const DeviceErrorCode condition : reaction.conditions) {
        const auto code = static_cast<std::uint16_t>(condition);
        const bool limit_switch = condition == DeviceErrorCode::NegativeLimitSwitch ||
                                  condition == DeviceErrorCode::PositiveLimitSwitch;
        if (!limit_switch || device_control_.state() == DriveState::OperationEnable) {
            raise_device_error(code);
        }
    }
    for (const DeviceErrorCode warning : reaction.cleared) {
        if (errors_.active(static_cast<std::uint16_t>(warning))) {
            clear_warning(static_cast<std::uint16_t>(warning));
        }
    }
}

void Escon2Drive::command(std::uint16_t device_command) {
    on_controlword(
        static_cast<std::uint16_t>((controlword_ & ~kDeviceCommandBits) | device_command));
}

void Escon2Drive::follow_power_stage() {
    const bool on = device_control_.outputs().power_stage_on;
    if (on && !power_stage_on_) {
        calibrate_current_offset();
    }
    if (on != power_stage_on_) {
        power_stage_on_ = on;
        stop_.reset();
        on_mode_written(); // the mode starts over on the actual state
    }
}

// 7.1.21: the enable calibrates the current offset as the power stage comes on; a motor already
// turning spoils it ("Ensure the motor is stationary"), the next one at standstill clears it.
// The manual gives no threshold: faster than 10 rpm is turning.
void Escon2Drive::calibrate_current_offset() {
    constexpr double kStandstill = 10.0 * 2 * std::numbers::pi / 60; // rad/s
    if (std::abs(axis_.motor().state().speed) > kStandstill) {
        raise_device_error(kCurrentOffsetWarning);
    } else if (errors_.active(kCurrentOffsetWarning)) {
        clear_warning(kCurrentOffsetWarning);
    }
}

// 3.3: (target velocity + velocity offset) within ± max motor speed, ramped with the profile
// acceleration (speeding up) and deceleration (slowing down), both within max acceleration.
plant::AxisDemand Escon2Drive::velocity_mode(double now) {
    const auto& od = objects();
    const double set_value = static_cast<double>(od.get_as<std::int32_t>(0x60FF, 0)) +
                             od.get_as<std::int32_t>(0x60B1, 0);
    const double max_rpm = od.get_as<std::uint32_t>(0x6080, 0);
    const double rpm = set_value * velocity_unit_in_rpm();
    set_value_limited_ = std::abs(rpm) > max_rpm;
    const double target = std::clamp(rpm, -max_rpm, max_rpm) * counts_per_rpm();
    const double max_acceleration = od.get_as<std::uint32_t>(0x60C5, 0);
    const motion::ProfileParameters profile{
        .acceleration = std::min<double>(od.get_as<std::uint32_t>(0x6083, 0), max_acceleration) *
                        counts_per_rpm(),
        .deceleration = std::min<double>(od.get_as<std::uint32_t>(0x6084, 0), max_acceleration) *
                        counts_per_rpm()};
    if (target != ramp_target_) {
        const motion::MotionState from = ramp_.sample(now - ramp_start_);
        ramp_ = motion::plan_velocity_change(from, target, profile);
        ramp_start_ = now;
        ramp_target_ = target;
    }
    demand_ = ramp_.sample(now - ramp_start_);
    return {.velocity = polarity() * demand_.velocity,
            .acceleration = polarity() * demand_.acceleration};
}

// 3.4: target current + current offset within ± output current limit; the velocity controller
// caps the speed at max motor speed when a main sensor is configured (3.4 note).
plant::AxisDemand Escon2Drive::current_mode() {
    const auto& od = objects();
    const double set_value = static_cast<double>(od.get_as<std::int32_t>(0x30F0, 0)) +
                             od.get_as<std::int32_t>(0x30F1, 0);
    const double limit = od.get_as<std::uint32_t>(0x3001, 2);
    const double max_speed = od.get_as<std::uint32_t>(0x6080, 0) * counts_per_rpm();
    const bool speed_capped = has_main_sensor() && std::abs(axis_.velocity_actual()) >= max_speed;
    set_value_limited_ = std::abs(set_value) > limit || speed_capped;
    demand_ = {static_cast<double>(axis_.position_actual()), axis_.velocity_actual(), 0};
    return {.current = polarity() * std::clamp(set_value, -limit, limit) / 1000.0,
            .speed_limit = has_main_sensor() ? max_speed : 0.0};
}

// Transitions 5, 8 (slow down with the profile deceleration), 11 and "f" errors (quick stop
// deceleration): the velocity falls from where it is to rest, then the device control goes on.
plant::AxisDemand Escon2Drive::stop_ramp(double now) {
    const auto& od = objects();
    if (!stop_) {
        const bool quick = device_control_.outputs().ramp == motion::StopRamp::QuickStop;
        const double deceleration = std::min(od.get_as<std::uint32_t>(quick ? 0x6085 : 0x6084, 0),
                                             od.get_as<std::uint32_t>(0x60C5, 0)) *
                                    counts_per_rpm();
        const motion::MotionState from =
            mode_ == OperatingMode::IoVelocity
                ? demand_
                : motion::MotionState{static_cast<double>(axis_.position_actual()),
                                      polarity() * axis_.velocity_actual(), 0};
        stop_ = motion::plan_stop(from, deceleration, motion::RampShape::Linear);
        stop_start_ = now;
        stop_completed_ = false;
    }
    demand_ = stop_->sample(now - stop_start_);
    if (!stop_completed_ && now - stop_start_ >= stop_->duration()) {
        stop_completed_ = true; // quick stop active stays at rest until 12 or 16
        device_control_.stop_completed();
    }
    return {.velocity = polarity() * demand_.velocity,
            .acceleration = polarity() * demand_.acceleration};
}

// The computed objects stored every period (the dictionary skips unchanged values' listeners
// only by their equality; these are cheap).
void Escon2Drive::publish() {
    auto& od = objects();
    od.set_as(0x6041, 0, statusword());
    od.set_as(0x606B, 0, rounded(to_velocity_units(demand_.velocity)));
    od.set_as(0x606C, 0, rounded(to_velocity_units(polarity() * axis_.velocity_actual())));
    od.set_as(0x30D0, 0, rounded(polarity() * axis_.current_demand() * 1000));
    od.set_as(0x30D1, 2, rounded(polarity() * axis_.current_actual() * 1000));
}

// Tables 17, 23, 99: the state bits, warning, bit 11 internal limit active, bit 12 follows the
// command value.
std::uint16_t Escon2Drive::statusword() const {
    std::uint16_t bits = device_control_.statusword();
    if (errors_.warning_active()) {
        bits |= motion::kWarningBit;
    }
    // Tables 19 / 25 "PWM max duty cycle": the supply voltage limits the current.
    constexpr double kAtMaxDuty = 0.99;
    const bool voltage_limited = pwm_duty_cycle() >= kAtMaxDuty * max_duty_cycle();
    if (set_value_limited_ || limitation_.limiting() || voltage_limited) {
        bits |= motion::kInternalLimitActiveBit;
    }
    if (device_control_.state() == DriveState::OperationEnable &&
        device_control_.outputs().ramp == motion::StopRamp::None) {
        bits |= kFollowsCommandValueBit;
    }
    return bits;
}

double Escon2Drive::seconds() const {
    return std::chrono::duration<double>(control_time_.time_since_epoch()).count();
}

// Quadcounts of the main sensor's encoder per motor turn, per minute.
double Escon2Drive::counts_per_rpm() const {
    return 4.0 * objects().get_as<std::uint32_t>(0x3010, 1) / 60.0;
}

double Escon2Drive::velocity_unit_in_rpm() const {
    return escon2::velocity_unit_in_rpm(objects().get_as<std::uint32_t>(0x60A9, 0));
}

double Escon2Drive::to_velocity_units(double counts_per_second) const {
    return counts_per_second / counts_per_rpm() / velocity_unit_in_rpm();
}

// 6.2.13.4 bit 0: inverse polarity turns the axis CW on positive demands.
double Escon2Drive::polarity() const {
    return (objects().get_as<std::uint32_t>(0x3000, 4) & 1U) != 0 ? -1.0 : 1.0;
}

bool Escon2Drive::has_main_sensor() const {
    return objects().get_as<std::uint32_t>(0x3000, 2) != kCurrentControlOnly;
}

} // namespace eposp::drives::escon2
