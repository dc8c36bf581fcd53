#include "eposp/drives/epos2/epos2_drive.hpp"

#include "axis_configuration.hpp"
#include "eposp/canopen/entry_builder.hpp"
#include "eposp/drives/epos2/device_errors.hpp"
#include "eposp/drives/epos2/epos2_io.hpp"
#include "eposp/drives/motion/device_error_codes.hpp"
#include "eposp/drives/motion/nearest_integer.hpp"
#include "eposp/drives/motion/profile_planner.hpp"
#include "eposp/drives/motion/software_position_limit.hpp"
#include "eposp/drives/motion/statusword_bits.hpp"
#include "modes/analog_setpoint.hpp"
#include "modes/mode_behaviour.hpp"
#include "modes/mode_table.hpp"
#include "velocity_units.hpp"
#include "write_rules.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace eposp::drives::epos2 {
namespace {

using motion::DriveState;
using motion::MotionState;

// 7.3, figure 7-54 remark *3 and table 7-65: statusword bit 9 is TRUE in NMT Operational only.
constexpr std::uint16_t kRemoteBit = 1U << 9;

// Table 3-6: the controlword bits of the device commands (0 … 3) and fault reset (7).
constexpr std::uint16_t kDeviceCommandBits = 0x008F;

// Table 4-11: the errors of the power stage and the CAN controller (4.2.3, 4.2.5, 4.2.6, 4.2.18).
constexpr std::uint16_t kOvercurrentErrorCode = 0x2310;
constexpr std::uint16_t kShortCircuitErrorCode = 0x2320;      // 4.2.4
constexpr std::uint16_t kLogicSupplyTooLowErrorCode = 0x5113; // 4.2.8
constexpr std::uint16_t kOvervoltageErrorCode = 0x3210;
constexpr std::uint16_t kUndervoltageErrorCode = 0x3220;
constexpr std::uint16_t kOvertemperatureErrorCode = 0x4210;
constexpr std::uint16_t kCanBusOffErrorCode = 0x81FD;
constexpr std::uint16_t kCanPassiveErrorCode = 0x8120;
constexpr std::uint16_t kCanRxQueueOverflowErrorCode = 0x81FE;
constexpr std::uint16_t kCanTxQueueOverflowErrorCode = 0x81FF;
constexpr std::uint16_t kPositionSensorErrorCode = 0x7320;   // 4.2.12
constexpr std::uint16_t kControllerGainErrorCode = 0xFF10;   // 4.2.36
constexpr std::uint16_t kSystemOverloadedErrorCode = 0xFF0B; // 4.2.32
// The target values of the modes (table 8-118): position, velocity, the Position, Velocity and
// Current Mode setting values, the IPM data record.
constexpr std::array<std::uint16_t, 6> kTargetValueObjects{0x607A, 0x60FF, 0x2062,
                                                           0x206B, 0x2030, 0x20C1};

// Table 8-125 and 8-102: the motor types with hall sensors, the main sensor types of encoder 1.
constexpr std::uint16_t kSinusoidalEcMotor = 10;
constexpr std::uint16_t kTrapezoidalEcMotor = 11;
constexpr std::uint16_t kEncoder1WithIndex = 1;
constexpr std::uint16_t kEncoder1WithoutIndex = 2;
// Table 4-11: the sensor errors (4.2.23 - 4.2.26, 4.2.29, 4.2.31).
constexpr motion::SensorErrorCodes kSensorErrorCodes{.encoder_breach = 0xFF0A,
                                                     .index_not_found = 0xFF02,
                                                     .encoder_resolution = 0xFF03,
                                                     .hall_sensor_not_found = 0xFF04,
                                                     .hall_signal = 0xFF01,
                                                     .hall_angle = 0xFF08};
// 8.2.41, table 8-83: "Disable sensor supervision by hardware".
constexpr std::uint16_t kNoHardwareSupervisionBit = 1U << 1;
constexpr std::uint16_t kNoSoftwareSupervisionBit = 1U << 0;
constexpr std::uint16_t kMainSensorDirectionErrorCode = 0xFF11; // 4.2.37
constexpr std::uint16_t kInversePolarityBit = 1U << 8;

// Table 4-11: CAN errors (0x81xx, 0x82xx) are "a" errors, reacting after 0x6007.
bool is_communication_error(std::uint16_t code) {
    return (code & 0xFF00) == 0x8100 || (code & 0xFF00) == 0x8200;
}

constexpr std::chrono::microseconds kControlPeriod{1000};

} // namespace

Epos2Drive::Epos2Drive(core::EventLoop& loop, can::Port& port, Epos2DriveConfig config)
    : loop_(loop), dictionary_(with_restore_rule(std::move(config.dictionary), *this)),
      node_(loop, port, dictionary_.objects(), dictionary_.node_config()), machine_(config.axis),
      axis_(config.axis), power_stage_temperature_(config.power_stage_thermal),
      mode_services_(std::make_unique<ModeServices>(ModeServices{
          .objects = dictionary_.objects(),
          .outputs = dictionary_.objects(),
          .counts_per_turn = counts_per_turn_,
          .rpm_per_velocity_unit = rpm_per_velocity_unit_,
          .digital_position_counter = digital_position_counter_,
          .raise_device_error = [this](std::uint16_t code) { raise_device_error(code); },
          .homing = homing_,
          .standstill = standstill_,
          .switches =
              [this] {
                  return switches();
              }})),
      mode_behaviour_(make_mode_behaviour(OperatingMode::ProfilePosition, *mode_services_)),
      control_time_(loop.now() + kControlPeriod),
      control_timer_(loop,
                     loop.every(kControlPeriod, control_time_, [this] { control_period(); })) {
    // The machine's encoder, gains and motor data are the device's defaults (8.2.74,
    // 8.2.125 - 8.2.130); from then on the dictionary configures the plant.
    write_axis_defaults(dictionary_.objects(), machine_);
    auto& od = dictionary_.objects();
    published_entries_ = {.statusword = od.value_ref(0x6041, 0),
                          .position_demand = od.value_ref(0x6062, 0),
                          .position_actual = od.value_ref(0x6064, 0),
                          .velocity_demand = od.value_ref(0x606B, 0),
                          .velocity_actual = od.value_ref(0x606C, 0),
                          .current_actual = od.value_ref(0x6078, 0),
                          .digital_inputs = od.value_ref(0x2071, 1)};
    configure_axis();
    read_counts_per_turn();
    read_units_and_polarity();
    io_ = std::make_unique<Epos2Io>(dictionary_.objects());
    read_sensor_configuration();
    watch_dictionary();
    compute_measured_values();
    compute_analog_setpoints(dictionary_.objects());
    // 8.2.62 and the "Disable state" objects: refused while the power stage is on.
    guard_disable_state_objects(dictionary_.objects(),
                                [this] { return device_control_.outputs().power_stage_on; });
    guard_analog_input_assignment(dictionary_.objects());
    guard_gear_configuration(dictionary_.objects());
    node_.on_reset_application([this] { reset_application(); });
    // The remote bit changes with the NMT state, between two control periods: stored at once, so
    // that the first TPDO in Operational carries it.
    node_.nmt().on_state_change([this](canopen::NmtState) {
        if (published_) {
            published_->statusword = statusword();
            dictionary_.objects().set_as(0x6041, 0, published_->statusword);
        }
    });
    // 4.2.15, 4.2.18: the CAN controller going error-passive or bus-off is an "a" error.
    node_.on_controller_state([this](can::ErrorState state) {
        if (state == can::ErrorState::Passive) {
            raise_device_error(kCanPassiveErrorCode);
        } else if (state == can::ErrorState::BusOff) {
            raise_device_error(kCanBusOffErrorCode);
        }
    });
    // 4.2.19, 4.2.20: the controller's receive and transmit queues are the virtual bus port's
    // (the spec gives no sizes for the EPOS2's). Raised at the next control period: a transmit
    // overflow is heard inside a send, where an EMCY would be sent again. The EMCY producer keeps
    // an EMCY the full queue refused until there is room (4.1: an EMCY "per error event").
    if (auto* virtual_port = dynamic_cast<can::VirtualPort*>(&port)) {
        virtual_port->on_overflow([this](can::Overflow overflow, const can::Frame&) {
            queue_overflow_ = overflow == can::Overflow::Receive ? kCanRxQueueOverflowErrorCode
                                                                 : kCanTxQueueOverflowErrorCode;
        });
    }
}

// 8.2.9: "Restoring of the default parameters is permitted in 'Power Disable' state and
// 'Pre-Operational NMT' state only." Power Disable is the group of figure 3-3 before Switched On.
Epos2DictionaryConfig Epos2Drive::with_restore_rule(Epos2DictionaryConfig config,
                                                    Epos2Drive& drive) {
    config.restore.restore_permitted = [&drive] {
        const DriveState state = drive.device_control_.state();
        const bool power_disabled =
            state == DriveState::Start || state == DriveState::NotReadyToSwitchOn ||
            state == DriveState::SwitchOnDisabled || state == DriveState::ReadyToSwitchOn;
        return power_disabled && drive.node_.nmt_state() == canopen::NmtState::PreOperational
                   ? canopen::AbortCode::None
                   : canopen::AbortCode::DeviceState;
    };
    return config;
}

void Epos2Drive::set_supply_voltage(double volts) {
    machine_.plant.power_stage.supply_voltage = volts;
    configure_axis();
    device_control_.set_fault_condition_present(fault_condition_present());
}

// A fault reset is refused while the supply, the power stage's temperature or the sensors' 5 V
// supply is out of range (4.2.5 - 4.2.8: "only possible if ... in valid range").
bool Epos2Drive::fault_condition_present() const {
    return fault_condition_present(supply_error(), power_stage_temperature_.too_high());
}

bool Epos2Drive::fault_condition_present(const std::optional<std::uint16_t>& supply,
                                         bool too_hot) const {
    return supply.has_value() || too_hot || sensor_faults_.supply_overloaded;
}

void Epos2Drive::set_analog_input(AnalogInput input, std::int16_t millivolts) {
    dictionary_.objects().set_as(0x207C, static_cast<std::uint8_t>(input), millivolts);
}

// 4.2.5, 4.2.6: the supply out of the power stage's range.
std::optional<std::uint16_t> Epos2Drive::supply_error() const {
    const plant::PowerStageParameters& stage = machine_.plant.power_stage;
    if (stage.supply_voltage < stage.min_supply_voltage) {
        return kUndervoltageErrorCode;
    }
    if (stage.supply_voltage > stage.max_supply_voltage) {
        return kOvervoltageErrorCode;
    }
    return std::nullopt;
}

void Epos2Drive::configure_axis() {
    const auto& od = dictionary_.objects();
    axis_.reconfigure(configured_axis(od, machine_));
    // 8.2.130: mA, mA and 100 ms.
    i2t_.set_parameters({.continuous_current = od.get_as<std::uint16_t>(0x6410, 1) / 1000.0,
                         .output_current_limit = od.get_as<std::uint16_t>(0x6410, 2) / 1000.0,
                         .time_constant = od.get_as<std::uint16_t>(0x6410, 5) / 10.0});
}

Epos2Drive::~Epos2Drive() = default;

void Epos2Drive::start() {
    node_.start();
}

// 8.2.44 - 8.2.48, 8.2.51, 8.2.71, 8.2.97: measured values computed when read (SDO, and TPDOs
// when they sample), so that the 1 ms loop does not store what nobody reads. A change of them
// alone does not trigger an event-driven TPDO.
void Epos2Drive::compute_measured_values() {
    auto& od = dictionary_.objects();
    const auto computed = [&od](std::uint16_t index, auto read) {
        od.find(index, 0)->on_read = [read] {
            return canopen::encode(read());
        };
    };
    const auto rounded = [](double value) {
        return std::lround(value);
    };
    // The raw counter register (8.2.44, 8.2.45), modulo 2^32.
    computed(0x2020, [this] { return static_cast<std::uint32_t>(encoder_counter()); });
    computed(0x2021, [this] { return static_cast<std::uint32_t>(counter_at_index_); });
    computed(0x2022, [this] {
        return std::uint16_t{plant::hall_inputs(axis_.hall_sensors(), sensor_faults_)};
    });
    // 8.2.42: the bit rate in use, as a code of table 8-81 (0x2001 9 "automatic bit rate
    // detection" is what the node found: the bus's).
    // A rate of no code (a bus the EPOS2 could not run on) shows as 8, "not supported".
    computed(0x200A, [this] { return bit_rate_code(node_.bit_rate()).value_or(8); });
    computed(0x2027, [this, rounded] {
        return static_cast<std::int16_t>(rounded(current_averaged_.output() * 1000));
    });
    computed(0x2028, [this, rounded] {
        return static_cast<std::int32_t>(
            rounded(velocity_averaged_.output() / rpm_per_velocity_unit_));
    });
    computed(0x2031, [this, rounded] {
        return static_cast<std::int32_t>(rounded(polarity_ * axis_.current_demand() * 1000));
    });
    computed(0x20F4, [this, rounded] {
        const double error = last_demand_.position - static_cast<double>(position_actual());
        using Limits = std::numeric_limits<std::int16_t>;
        return static_cast<std::int16_t>(
            std::clamp<long>(rounded(error), Limits::min(), Limits::max()));
    });
    computed(0x6069,
             [this, rounded] { return static_cast<std::int32_t>(rounded(velocity_actual())); });
}

void Epos2Drive::watch_dictionary() {
    auto& od = dictionary_.objects();
    // Deferred to the end of the event: an RPDO maps the controlword before the target
    // (8.2.20), and a new setpoint must see the target of the same PDO. Queued in order, so
    // that no edge of a controlword written twice at one instant is lost.
    od.on_change(0x6040, [this](std::uint16_t, std::uint8_t) {
        pending_controlwords_.push_back(dictionary_.objects().get_as<std::uint16_t>(0x6040, 0));
        if (pending_controlwords_.size() == 1) {
            controlword_timer_ =
                core::ScopedTimer(loop_, loop_.post([this] { handle_pending_controlwords(); }));
        }
    });
    od.on_change(0x6060, [this](std::uint16_t, std::uint8_t) { on_mode_written(); });
    for (const std::uint16_t index : kAxisConfigurationObjects) {
        od.on_change(index, [this](std::uint16_t, std::uint8_t) { configure_axis(); });
    }
    // 8.2.74: the sensor configuration changed, the position is no longer referenced; another
    // main sensor type also clears the actual position.
    od.on_change(0x2210, [this](std::uint16_t, std::uint8_t sub) {
        read_counts_per_turn();
        if (sub == 2) {
            reset_actual_position();
        } else {
            homing_.reference_lost();
        }
    });
    for (const std::uint16_t index : std::array<std::uint16_t, 4>{0x2008, 0x2210, 0x2230, 0x6402}) {
        od.on_change(index, [this](std::uint16_t, std::uint8_t) { read_sensor_configuration(); });
    }
    // 8.2.130 sub 3: the pole pairs of the hall angle check.
    od.on_change(0x6410, [this](std::uint16_t, std::uint8_t sub) {
        if (sub == 3) {
            read_sensor_configuration();
        }
    });
    for (const std::uint16_t index : std::array<std::uint16_t, 2>{0x2008, 0x608B}) {
        od.on_change(index, [this](std::uint16_t, std::uint8_t) { read_units_and_polarity(); });
    }
    // 8.2.73: the standstill of the stop ramps and of PVM's speed zero.
    od.on_change(0x2101, [this](std::uint16_t, std::uint8_t) { read_standstill_window(); });
    for (const std::uint16_t option_code :
         std::array<std::uint16_t, 4>{0x6007, 0x605B, 0x605C, 0x605E}) {
        od.on_change(option_code, [this](std::uint16_t, std::uint8_t) { read_option_codes(); });
    }
    for (const std::uint16_t set_value : kSetValueObjects) {
        od.on_change(set_value, [this](std::uint16_t index, std::uint8_t sub_index) {
            mode_behaviour_->on_set_value_written(seconds(), index, sub_index);
        });
    }
    // 4.2.32: "not enough free resources to process new target value".
    for (const std::uint16_t target : kTargetValueObjects) {
        od.on_change(target, [this](std::uint16_t, std::uint8_t) {
            if (system_load_.overloaded() && device_control_.outputs().drive_function_enabled) {
                raise_device_error(kSystemOverloadedErrorCode);
            }
        });
    }
    od.on_change(0x1003, [this](std::uint16_t, std::uint8_t sub) {
        if (sub == 1) {
            on_error_recorded();
        }
    });
}

void Epos2Drive::handle_pending_controlwords() {
    // Nothing pending, nothing posted: the handler is posted with the first controlword queued
    // and cancelled with the queue drained (every control period asks).
    if (pending_controlwords_.empty()) {
        return;
    }
    controlword_timer_.cancel();
    while (!pending_controlwords_.empty()) {
        on_controlword(pending_controlwords_.front());
        pending_controlwords_.pop_front();
    }
}

// Power-on and NMT reset node (transition 19, then 0 and 1 of table 3-5).
void Epos2Drive::reset_application() {
    configure_axis(); // the reset restored values without telling the listeners
    read_counts_per_turn();
    read_units_and_polarity();
    io_->reload();
    read_sensor_configuration();
    read_standstill_window();
    read_option_codes();
    published_.reset(); // the reset stored the defaults behind the computed objects
    device_control_.node_reset();
    device_control_.initialise();
    device_control_.initialisation_finished();
    controlword_ = 0;
    mode_ = OperatingMode::ProfilePosition;
    on_mode_written();
    publish(MotionState{static_cast<double>(position_actual()), 0, 0});
}

// The mode starts over at rest on the actual position, also when the power stage comes on.
void Epos2Drive::on_mode_written() {
    const auto written = dictionary_.objects().get_as<std::int8_t>(0x6060, 0);
    mode_ = simulated_mode(written).value_or(OperatingMode::ProfilePosition);
    const std::int64_t here = position_actual();
    hold_position_ = static_cast<double>(here);
    mode_behaviour_ = make_mode_behaviour(mode_, *mode_services_);
    mode_behaviour_->start(seconds(), here, power_stage_on_);
    following_error_ =
        motion::FollowingErrorMonitor(dictionary_.objects().get_as<std::uint32_t>(0x6065, 0));
    position_limit_ = motion::SoftwarePositionLimitMonitor(
        {dictionary_.objects().get_as<std::int32_t>(0x607D, 1),
         dictionary_.objects().get_as<std::int32_t>(0x607D, 2)});
    // 8.2.91: the display follows the mode once it is active.
    dictionary_.objects().set_as(0x6061, 0, written);
}

void Epos2Drive::on_controlword(std::uint16_t controlword) {
    const std::uint16_t rising = controlword & ~controlword_;
    const std::uint16_t falling = controlword_ & ~controlword;
    controlword_ = controlword;
    const DriveState before = device_control_.state();
    device_control_.write_controlword(controlword);
    if (before == DriveState::Fault && device_control_.state() != DriveState::Fault) {
        clear_errors();
    }
    const auto enabled = [](DriveState state) { // the Enable Operation command's way (3.2.3)
        return state == DriveState::Refresh || state == DriveState::MeasureInit ||
               state == DriveState::OperationEnable;
    };
    if (!enabled(before) && enabled(device_control_.state()) &&
        commutation_resolution_too_low()) {
        raise_device_error(kPositionSensorErrorCode);
    }
    mode_behaviour_->on_controlword({.now = seconds(),
                                     .controlword = controlword,
                                     .rising = rising,
                                     .falling = falling,
                                     .enabled = device_control_.outputs().drive_function_enabled,
                                     .last_demand = last_demand_});
}

// 3.2.3 transition 15: fault reset ends every error (one EMCY 0x0000). Table 4-11, "Position
// Reset": clearing a sensor error resets the actual position (to 0, no longer referenced) and
// the sensors start up again.
void Epos2Drive::clear_errors() {
    node_.emcy().clear_all();
    following_error_ =
        motion::FollowingErrorMonitor(dictionary_.objects().get_as<std::uint32_t>(0x6065, 0));
    if (position_reset_on_clear_) {
        position_reset_on_clear_ = false;
        reset_actual_position();
        restart_sensor_supervision();
    }
}

// The actual position starts again at 0, no longer referenced.
void Epos2Drive::reset_actual_position() {
    position_offset_ = -encoder_counter();
    homing_.reference_lost();
}

// 8.2.74: "The pulse number of incremental encoder 1 must be greater or equal to (16 * pole pair
// number)" where it is the sinus commutation's encoder; checked at the Enable Operation command.
bool Epos2Drive::commutation_resolution_too_low() const {
    const auto& od = dictionary_.objects();
    const auto main_sensor = od.get_as<std::uint16_t>(0x2210, 2) & 0xF;
    return od.get_as<std::uint16_t>(0x6402, 0) == kSinusoidalEcMotor &&
           (main_sensor == kEncoder1WithIndex || main_sensor == kEncoder1WithoutIndex) &&
           od.get_as<std::uint32_t>(0x2210, 1) < 16U * od.get_as<std::uint8_t>(0x6410, 3);
}

// 4.2: an error recorded in 0x1003 that the node's services raised (heartbeat, guarding, PDO
// length, SYNC): the "a" fault reaction.
void Epos2Drive::on_error_recorded() {
    const auto entry = dictionary_.objects().get_as<std::uint32_t>(0x1003, 1);
    const auto code = static_cast<std::uint16_t>(entry & 0xFFFF);
    if (is_communication_error(code)) {
        device_control_.fault_occurred(motion::FaultClass::Communication);
    }
}

// 4.1, table 4-11: the error's register bits in 0x1001 and its EMCY, the history entry, and the
// reaction of its class.
void Epos2Drive::raise_device_error(std::uint16_t code) {
    const DeviceError& error = device_error(code);
    position_reset_on_clear_ = position_reset_on_clear_ || error.position_reset;
    node_.emcy().raise(code, error.error_register);
    device_control_.fault_occurred(error.reaction);
}

// 4.2.3 - 4.2.8: the power stage's supervision: current, short circuit, supply, temperature, and
// the sensors' 5 V supply.
void Epos2Drive::watch_power_stage(bool overcurrent) {
    power_stage_temperature_.update(axis_.current_actual(), power_stage_on_,
                                    plant::ServoAxis::kOuterLoopPeriod);
    // Each cause read once, for the fault condition and the errors.
    const std::optional<std::uint16_t> supply = supply_error();
    const bool too_hot = power_stage_temperature_.too_high();
    device_control_.set_fault_condition_present(fault_condition_present(supply, too_hot));
    if (supply) {
        raise_device_error(*supply);
    }
    if (too_hot) {
        raise_device_error(kOvertemperatureErrorCode);
    }
    if (sensor_faults_.supply_overloaded) {
        raise_device_error(kLogicSupplyTooLowErrorCode);
    }
    // 4.2.4: the power stage driver finds the short once it drives the winding, before the
    // current it would let through is measured.
    if (winding_shorted_ && power_stage_on_) {
        raise_device_error(kShortCircuitErrorCode);
    }
    if (overcurrent) {
        raise_device_error(kOvercurrentErrorCode);
    }
}

// One millisecond: the device control's pending transitions, the mode's demand, ten steps of
// the current loop and the plant, the monitors, the computed objects. It runs at control_time_,
// the timer's scheduled time, and never at the loop's now(): a real-time loop running late
// calls it in a burst while now() shows the wall clock, and the physics would follow the host's
// load (the timer fires once per period, in order, so counting the periods is its schedule).
void Epos2Drive::control_period() {
    const double now = seconds();
    // A controlword written before this period's time acts now, also when a real-time loop
    // running late posted its handling behind this period (now() was the wall clock then).
    handle_pending_controlwords();
    finish_device_control_transitions();
    follow_power_stage();
    const motion::DriveOutputs outputs = device_control_.outputs();
    // Stop ramps and holding run on the position loop; the mode chooses its loop (5.9, 5.12,
    // 5.14).
    ModeDemand commanded{.motion = {static_cast<double>(position_actual()), 0, 0}};
    if (outputs.ramp != motion::StopRamp::None) {
        commanded.motion = stop_ramp(now);
    } else if (outputs.drive_function_enabled) {
        commanded = mode_behaviour_->demand(mode_inputs());
        if (commanded.position_offset) {
            position_offset_ += *commanded.position_offset;
            // 8.2.68: the home found, in the coordinates before, minus the Home Position.
            dictionary_.objects().set_as(0x2082, 0,
                                         static_cast<std::int32_t>(-*commanded.position_offset));
        }
    } else if (power_stage_on_) {
        commanded.motion = MotionState{hold_position_, 0, 0}; // where the power stage came on
    }
    index_latch_.reset();
    const MotionState demand = commanded.motion;
    axis_.set_mode(power_stage_on_ ? commanded.loop : plant::ControlMode::PowerOff);
    if (controller_gain_missing(axis_.parameters().gains, axis_.mode())) {
        raise_device_error(kControllerGainErrorCode);
    }
    axis_.set_demand(
        {.position = polarity_ * (demand.position - static_cast<double>(position_offset_)),
         .velocity = polarity_ * demand.velocity,
         .acceleration = polarity_ * demand.acceleration,
         .current = polarity_ * commanded.current,
         .speed_limit = commanded.speed_limit});
    const double overcurrent = machine_.plant.power_stage.overcurrent;
    bool overcurrent_seen = false;
    for (int step = 0; step < plant::ServoAxis::kCurrentStepsPerOuterLoop; ++step) {
        axis_.step();
        if (axis_.index_passed() && !sensor_faults_.index_missing &&
            !sensor_faults_.encoder_silent()) {
            index_latch_ = position_actual();
            counter_at_index_ = encoder_counter();
        }
        // Read once: the filters' stores would make the compiler read it again for each use.
        const double motor_current = axis_.current_actual();
        current_averaged_.update(polarity_ * motor_current); // current_actual()
        i2t_.update(motor_current, plant::ServoAxis::kCurrentLoopPeriod);
        overcurrent_seen = overcurrent_seen || std::abs(motor_current) > overcurrent;
    }
    axis_.reduce_current_limit(i2t_.limit()); // 5.14.1
    watch_power_stage(overcurrent_seen);
    watch_sensors();
    watch_bus_queues();
    velocity_averaged_.update(counts_to_rpm(velocity_actual()));
    last_demand_ = demand;
    watch_motion(demand);
    watch_io(now);
    publish(demand);
    control_time_ += kControlPeriod;
}

void Epos2Drive::watch_sensors() {
    // The sensors are unpowered: 0x5113 is the cause the drive reports, what the supervision would
    // find without the sensors' signals is its consequence.
    if (sensor_faults_.supply_overloaded) {
        return;
    }
    if (const auto fault = sensor_supervision_.update(axis_.encoder_angle(), axis_.hall_sensors(),
                                                      sensor_faults_)) {
        raise_device_error(kSensorErrorCodes.of(*fault));
    }
    // The motor's turning shows at its terminals only with the power stage on.
    const bool watching = power_stage_on_ && software_supervision_;
    if (sensor_direction_.update(watching ? axis_.motor().state().speed : 0,
                                 axis_.position_actual())) {
        raise_device_error(kMainSensorDirectionErrorCode);
    }
}

void Epos2Drive::watch_bus_queues() {
    if (queue_overflow_) {
        raise_device_error(*queue_overflow_);
        queue_overflow_.reset();
    }
}

// 8.2.74, 8.2.41, 8.2.127: what the sensor supervision checks; a new configuration is a start-up.
void Epos2Drive::read_sensor_configuration() {
    const auto& od = dictionary_.objects();
    const auto main_sensor = static_cast<std::uint16_t>(od.get_as<std::uint16_t>(0x2210, 2) & 0xF);
    const auto motor_type = od.get_as<std::uint16_t>(0x6402, 0);
    const bool encoder = main_sensor == kEncoder1WithIndex || main_sensor == kEncoder1WithoutIndex;
    const bool hall_sensors = motor_type == kSinusoidalEcMotor || motor_type == kTrapezoidalEcMotor;
    const double motor_turns_per_encoder_turn = motor_turns_per_sensor_turn(od);
    sensor_supervision_.configure(
        {.encoder_pulses = static_cast<int>(od.get_as<std::uint32_t>(0x2210, 1)),
         .encoder = encoder,
         .encoder_index = main_sensor == kEncoder1WithIndex,
         .hall_sensors = hall_sensors,
         .breach_supervision =
             (od.get_as<std::uint16_t>(0x2008, 0) & kNoHardwareSupervisionBit) == 0,
         // 4.2.29: the encoder's angle against the Hall sensors', both on the motor shaft. With a
         // gear the encoder is on its output (8.2.74): a count there spans more of the motor's
         // electrical turn than the check's tolerance, so there is nothing to compare.
         .hall_angle = encoder && hall_sensors && motor_turns_per_encoder_turn == 1,
         .pole_pairs = od.get_as<std::uint8_t>(0x6410, 3),
         .motor_turns_per_encoder_turn = motor_turns_per_encoder_turn});
    software_supervision_ = (od.get_as<std::uint16_t>(0x2008, 0) & kNoSoftwareSupervisionBit) == 0;
    // A quarter turn of the encoder against the motor (4.2.37; the spec gives no threshold).
    sensor_direction_ = motion::SensorDirectionMonitor(od.get_as<std::uint32_t>(0x2210, 1),
                                                       axis_.position_actual());
    restart_sensor_supervision();
}

void Epos2Drive::restart_sensor_supervision() {
    sensor_supervision_.restart(axis_.encoder_angle(), axis_.hall_sensors(), sensor_faults_);
}

// Refresh (20) and Measure Init (21) take one control period here, and so does a fault reaction
// that only disables the drive (13, or 17 with "disable drive"): it has no ramp to wait for, the
// power stage is off once it is done (14, 18).
void Epos2Drive::finish_device_control_transitions() {
    const DriveState state = device_control_.state();
    if (state == DriveState::Refresh) {
        device_control_.refresh_finished();
    } else if (state == DriveState::MeasureInit) {
        // 8.2.72: Operation Enable once the holding brake has let go (its fall time).
        if (io_->operation_may_start(seconds())) {
            device_control_.measure_init_finished();
        }
    } else if ((state == DriveState::FaultReactionActiveDisabled ||
                state == DriveState::FaultReactionActiveEnabled) &&
               device_control_.outputs().ramp == motion::StopRamp::None) {
        device_control_.stop_completed();
    }
}

// Power stage switched on: the controllers start on the actual position, at rest.
void Epos2Drive::follow_power_stage() {
    const bool requested = device_control_.outputs().power_stage_on;
    const DriveState state = device_control_.state();
    const bool fault = state == DriveState::FaultReactionActiveDisabled ||
                       state == DriveState::FaultReactionActiveEnabled ||
                       state == DriveState::Fault;
    const bool on = io_->power_stage(seconds(), requested, fault, velocity_averaged_.output());
    if (on && !requested) {
        hold_position_ = last_demand_.position; // 8.2.72: held until the brake holds
    }
    if (on == power_stage_on_) {
        return;
    }
    power_stage_on_ = on;
    axis_.set_mode(on ? plant::ControlMode::Position : plant::ControlMode::PowerOff);
    stopping_ = false;
    if (on) {
        on_mode_written();
    } else {
        mode_behaviour_->drive_disabled(seconds());
    }
}

// A quickstop, slow-down or fault reaction ramp (3.2.3): the demand stops from where it is
// with the quickstop (0x6085) or the mode's deceleration; the device control hears when the axis
// stands still (8.2.73) or the standstill timeout elapsed.
MotionState Epos2Drive::stop_ramp(double now) {
    const auto& od = dictionary_.objects();
    if (!stopping_) {
        stopping_ = true;
        const bool quick = device_control_.outputs().ramp == motion::StopRamp::QuickStop;
        stop_ = motion::plan_stop(
            last_demand_, rpm_to_counts(od.get_as<std::uint32_t>(quick ? 0x6085 : 0x6084, 0)),
            static_cast<motion::RampShape>(od.get_as<std::int16_t>(0x6086, 0)));
        stop_start_ = now;
        standstill_.stop_started(now);
        mode_behaviour_->drive_disabled(now);
    }
    const MotionState demand = stop_.sample(now - stop_start_);
    standstill_.update(now, counts_to_rpm(velocity_actual()),
                       now - stop_start_ >= stop_.duration());
    if (standstill_.stop_completed(now)) {
        stopping_ = false;
        // The mode starts over at rest where the stop ended, its setpoints dropped.
        mode_behaviour_->stop_completed(demand.position);
        device_control_.stop_completed();
    }
    return demand;
}

ModeInputs Epos2Drive::mode_inputs() const {
    return {.now = seconds(),
            .controlword = controlword_,
            .position = position_actual(),
            .velocity = velocity_actual(),
            .current = current_actual(),
            .index_position = index_latch_};
}

// Following error (5.9.1.2) in the position-controlled modes; target reached and speed zero.
void Epos2Drive::watch_motion(const MotionState& demand) {
    const auto actual = static_cast<double>(position_actual());
    if (power_stage_on_ && device_control_.state() != DriveState::Fault) {
        if (mode_behaviour_->position_controlled()) {
            if (const auto error = following_error_.update(demand.position, actual)) {
                raise_device_error(*error);
            }
        }
        // 8.2.105: the actual position leaving the limits; homing runs before the limits mean
        // anything (they are relative to the home position).
        if (mode_behaviour_->supervises_limits()) {
            if (const auto error = position_limit_.update(actual)) {
                raise_device_error(*error);
            }
        }
    }
    mode_behaviour_->watch(mode_inputs(), demand);
}

// 8.2.56 - 8.2.61: the digital inputs and what they execute (limit switch errors 0xFF06 / 0xFF07,
// quickstop and device enable as device commands, the marker's Single & Stop as a Halt), the
// position marker and compare, the digital outputs.
void Epos2Drive::watch_io(double now) {
    const IoReaction reaction = io_->update({.now = now,
                                             .position = position_actual(),
                                             .state = device_control_.state(),
                                             .power_stage_on = power_stage_on_,
                                             .homing_mode = !mode_behaviour_->supervises_limits(),
                                             .homing_in_progress = homing_.in_progress(),
                                             .machine_switches = axis_.switches()});
    if (reaction.negative_limit_error) {
        raise_device_error(motion::kNegativeLimitSwitchErrorCode);
    }
    if (reaction.positive_limit_error) {
        raise_device_error(motion::kPositiveLimitSwitchErrorCode);
    }
    for (const std::uint16_t command : reaction.device_commands) {
        on_controlword(static_cast<std::uint16_t>((controlword_ & ~kDeviceCommandBits) | command));
    }
    if (reaction.stop) {
        on_controlword(static_cast<std::uint16_t>(controlword_ | kHaltBit));
    }
}

// 8.2.86: the state bits (table 3-4), the mode's bits (table 8-114) and Remote.
std::uint16_t Epos2Drive::statusword() const {
    const bool remote = node_.nmt_state() == canopen::NmtState::Operational;
    // Table 8-114: bits 15 and 11 (I²t, 5.14.1) in every mode, bits 10, 12, 13 the present mode's.
    const std::uint16_t mode_bits = static_cast<std::uint16_t>(
        (homing_.referenced() ? motion::kPositionReferencedBit : 0) |
        (i2t_.limiting() ? motion::kInternalLimitActiveBit : 0) |
        mode_behaviour_->statusword_bits(seconds(), following_error_.active()));
    return static_cast<std::uint16_t>(device_control_.statusword() | mode_bits |
                                      (remote ? kRemoteBit : 0));
}

std::uint16_t Epos2Drive::digital_input_states() const {
    return io_->displayed_inputs(axis_.switches());
}

plant::SwitchStates Epos2Drive::switches() const {
    return io_->switch_functions(axis_.switches());
}

// A switch held from outside acts from the next control period on, like one the axis reaches.
void Epos2Drive::hold_limit_switch(LimitSwitch which, bool pressed) {
    io_->hold_limit_switch(which == LimitSwitch::Negative ? InputFunction::NegativeLimitSwitch
                                                          : InputFunction::PositiveLimitSwitch,
                           pressed);
}

void Epos2Drive::set_digital_input(unsigned input, bool high) {
    io_->set_input(input, high);
}

bool Epos2Drive::digital_input(unsigned input) const {
    return io_->input(input, axis_.switches());
}

bool Epos2Drive::digital_output(unsigned output) const {
    return io_->output(output);
}

// The computed objects (8.2.86, 8.2.92 - 8.2.97, 8.2.57), stored when they change so that the
// listeners of event-driven TPDOs hear it.
void Epos2Drive::publish(const MotionState& demand) {
    const auto to_i32 = [](double value) {
        return static_cast<std::int32_t>(motion::nearest_integer(value));
    };
    const PublishedValues now{
        .statusword = statusword(),
        .position_demand = to_i32(demand.position),
        .position_actual = static_cast<std::int32_t>(position_actual()),
        .velocity_demand = to_i32(counts_to_velocity(demand.velocity)),
        .velocity_actual = to_i32(counts_to_velocity(velocity_actual())),
        .current_actual =
            static_cast<std::int16_t>(motion::nearest_integer(current_actual() * 1000)),
        .digital_inputs = digital_input_states(),
    };
    // Compared with what was stored last, not read back: a dictionary read per object and
    // millisecond would cost more than the whole motor model.
    auto& od = dictionary_.objects();
    const auto store = [&od, this](canopen::ValueRef entry, auto value, auto last) {
        if (!published_ || value != last) {
            od.set_as(entry, value);
        }
    };
    const PublishedValues& last = published_.value_or(now);
    const PublishedEntries& at = published_entries_;
    store(at.statusword, now.statusword, last.statusword);
    store(at.position_demand, now.position_demand, last.position_demand);
    store(at.position_actual, now.position_actual, last.position_actual);
    store(at.velocity_demand, now.velocity_demand, last.velocity_demand);
    store(at.velocity_actual, now.velocity_actual, last.velocity_actual);
    store(at.current_actual, now.current_actual, last.current_actual);
    store(at.digital_inputs, now.digital_inputs, last.digital_inputs);
    published_ = now;
}

double Epos2Drive::seconds() const {
    return std::chrono::duration<double>(control_time_.time_since_epoch()).count();
}

// 8.2.84, 8.2.87 - 8.2.89.
void Epos2Drive::read_option_codes() {
    const auto& od = dictionary_.objects();
    device_control_.set_option_codes({.abort_connection = od.get_as<std::int16_t>(0x6007, 0),
                                      .shutdown = od.get_as<std::int16_t>(0x605B, 0),
                                      .disable_operation = od.get_as<std::int16_t>(0x605C, 0),
                                      .fault_reaction = od.get_as<std::int16_t>(0x605E, 0)});
}

// 8.2.73: read when written.
void Epos2Drive::read_standstill_window() {
    standstill_ = motion::StandstillMonitor(standstill_window(dictionary_.objects()));
}

// 3.3: the velocity unit; 8.2.41 table 8-83 bit 8: "1 = Inverse: If demanded velocity or position
// is positive, direction of rotation is CW".
void Epos2Drive::read_units_and_polarity() {
    const auto& od = dictionary_.objects();
    rpm_per_velocity_unit_ = rpm_per_velocity_unit(od);
    polarity_ = (od.get_as<std::uint16_t>(0x2008, 0) & kInversePolarityBit) != 0 ? -1 : 1;
}

// 8.2.74: quadcounts are four per encoder pulse.
void Epos2Drive::read_counts_per_turn() {
    counts_per_turn_ = 4.0 * dictionary_.objects().get_as<std::uint32_t>(0x2210, 1);
}

} // namespace eposp::drives::epos2
