#include "eposp/drives/epos2/epos2_io.hpp"

#include "eposp/canopen/entry_builder.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace eposp::drives::epos2 {
namespace {

using motion::DriveState;

// Table 3-6 device commands (controlword bits 0 … 3, 7) that the inputs execute.
constexpr std::array<std::uint16_t, 1> kQuickStop{0x0002};
constexpr std::array<std::uint16_t, 1> kDisableVoltage{0x0000};
// Fault reset (when in Fault), Shutdown, Switch On & Enable Operation.
constexpr std::array<std::uint16_t, 3> kEnable{0x0080, 0x0006, 0x000F};

// Table 8-94 "Ready / Fault": active when the device is ready, inactive on a fault.
bool device_ready(DriveState state) {
    switch (state) {
    case DriveState::Start:
    case DriveState::NotReadyToSwitchOn:
    case DriveState::FaultReactionActiveDisabled:
    case DriveState::FaultReactionActiveEnabled:
    case DriveState::Fault:
        return false;
    default:
        return true;
    }
}

} // namespace

motion::StandstillWindow standstill_window(const canopen::ObjectDictionary& od) {
    return {.window = od.get_as<std::uint16_t>(0x2101, 1),
            .time_ms = od.get_as<std::uint16_t>(0x2101, 2),
            .timeout_ms = od.get_as<std::uint16_t>(0x2101, 3)};
}

Epos2Io::Epos2Io(canopen::ObjectDictionary& od) : od_(od) {
    reload();
    od.on_change(0x2070, [this](std::uint16_t, std::uint8_t) { read_inputs(); });
    od.on_change(0x2071, [this](std::uint16_t, std::uint8_t sub) {
        if (sub != 1) {
            read_inputs();
        }
    });
    od.on_change(0x2074, [this](std::uint16_t, std::uint8_t sub) {
        if (sub == 4) {
            counter_written();
        } else if (sub == 2 || sub == 3) {
            read_marker();
        }
    });
    od.on_change(0x2078, [this](std::uint16_t, std::uint8_t sub) {
        if (sub == 1) {
            outputs_written();
        } else {
            read_outputs();
        }
    });
    od.on_change(0x2079, [this](std::uint16_t, std::uint8_t) {
        read_outputs();
        read_brake();
    });
    od.on_change(0x207A, [this](std::uint16_t, std::uint8_t) { read_compare(); });
    od.on_change(0x2210, [this](std::uint16_t, std::uint8_t) { read_compare(); });
    od.on_change(0x2100, [this](std::uint16_t, std::uint8_t) { read_brake(); });
    od.on_change(0x2101, [this](std::uint16_t, std::uint8_t) { read_brake(); });
    guard_brake_output();
}

// 8.2.60: "Changes for Holding Brake Configuration are only supported in 'Disable' state": an
// output becoming or ceasing to be the brake output is refused while the power stage is on.
void Epos2Io::guard_brake_output() {
    constexpr auto kBrake = static_cast<std::uint16_t>(OutputFunction::HoldingBrake);
    for (std::uint8_t n = 1; n <= kDigitalOutputCount; ++n) {
        canopen::Entry(*od_.find(0x2079, n)).rule([this, n](std::span<const std::uint8_t> value) {
            const auto now = canopen::decode<std::uint16_t>(value);
            const auto before = od_.get_as<std::uint16_t>(0x2079, n);
            const bool brake_changes = now != before && (now == kBrake || before == kBrake);
            return brake_changes && power_stage_on_ ? canopen::AbortCode::DeviceState
                                                    : canopen::AbortCode::None;
        });
    }
}

bool Epos2Io::power_stage(double now, bool requested, bool fault, double velocity_averaged) {
    power_stage_on_ = brake_.power_stage(now, requested, fault, velocity_averaged);
    return power_stage_on_;
}

void Epos2Io::reload() {
    read_inputs();
    read_outputs();
    read_marker();
    read_compare();
    read_brake();
    outputs_written();
    marker_.counter_written(od_.get_as<std::uint16_t>(0x2074, 4));
    marker_stored_ = {};
}

void Epos2Io::read_inputs() {
    DigitalInputConfiguration config;
    for (unsigned n = 0; n < kDigitalInputCount; ++n) {
        config.functions[n] = od_.get_as<std::uint16_t>(0x2070, static_cast<std::uint8_t>(n + 1));
    }
    config.mask = od_.get_as<std::uint16_t>(0x2071, 2);
    config.polarity = od_.get_as<std::uint16_t>(0x2071, 3);
    config.execution_mask = od_.get_as<std::uint16_t>(0x2071, 4);
    inputs_.configure(config);
}

void Epos2Io::read_outputs() {
    DigitalOutputConfiguration config;
    for (unsigned n = 0; n < kDigitalOutputCount; ++n) {
        config.functions[n] = od_.get_as<std::uint16_t>(0x2079, static_cast<std::uint8_t>(n + 1));
    }
    config.mask = od_.get_as<std::uint16_t>(0x2078, 2);
    config.polarity = od_.get_as<std::uint16_t>(0x2078, 3);
    outputs_.configure(config);
}

void Epos2Io::read_marker() {
    marker_.configure(static_cast<MarkerEdge>(od_.get_as<std::uint8_t>(0x2074, 2)),
                      static_cast<MarkerMode>(od_.get_as<std::uint8_t>(0x2074, 3)));
}

void Epos2Io::read_compare() {
    compare_.configure({.configuration = od_.get_as<std::uint16_t>(0x207A, 1),
                        .reference = od_.get_as<std::int32_t>(0x207A, 2),
                        .interval_width = od_.get_as<std::int32_t>(0x207A, 3),
                        .repetitions = od_.get_as<std::uint16_t>(0x207A, 4),
                        .pulse_width_us = od_.get_as<std::uint16_t>(0x207A, 5),
                        .sensor_type = od_.get_as<std::uint16_t>(0x2210, 2)});
}

void Epos2Io::read_brake() {
    brake_.configure(outputs_.configuration().has(OutputFunction::HoldingBrake),
                     {.rise_time = od_.get_as<std::uint16_t>(0x2100, 1),
                      .fall_time = od_.get_as<std::uint16_t>(0x2100, 2),
                      .timeout = od_.get_as<std::uint16_t>(0x2100, 3)},
                     standstill_window(od_));
}

// 8.2.59: the master writes the general purpose bits; "a write access has no effect" on bits
// 0 … 7, which are put back at once.
void Epos2Io::outputs_written() {
    const auto written = od_.get_as<std::uint16_t>(0x2078, 1);
    general_purpose_outputs_ = written & ~kFirmwareOutputBits;
    if ((written & kFirmwareOutputBits) != firmware_outputs_) {
        store_firmware_outputs(firmware_outputs_);
    }
}

void Epos2Io::store_firmware_outputs(std::uint16_t bits) {
    firmware_outputs_ = bits;
    od_.set_as(0x2078, 1, static_cast<std::uint16_t>(general_purpose_outputs_ | bits));
}

// 8.2.58: "The counter and the captured positions can be cleared by writing 0".
void Epos2Io::counter_written() {
    const auto counter = od_.get_as<std::uint16_t>(0x2074, 4);
    if (counter != marker_.counter()) {
        marker_.counter_written(counter);
        store_marker();
    }
}

void Epos2Io::store_marker() {
    const MarkerValues now{marker_.captured(), marker_.history(1), marker_.history(2),
                           marker_.counter()};
    if (now == marker_stored_) {
        return;
    }
    marker_stored_ = now;
    od_.set_as(0x2074, 1, now.captured);
    od_.set_as(0x2074, 5, now.history1);
    od_.set_as(0x2074, 6, now.history2);
    od_.set_as(0x2074, 4, now.counter);
}

IoReaction Epos2Io::update(const IoSample& sample) {
    IoReaction reaction;
    const std::uint16_t states = inputs_.states(sample.machine_switches);
    const std::uint16_t executed = inputs_.configuration().execution_mask;

    // 8.2.57, table 8-89 / 4.2.27, 4.2.28: a limit switch going active raises its error when
    // executed. Sampled only with the power stage on outside Fault, so that a switch pressed
    // meanwhile raises its error when the drive is next enabled; during homing the switches are
    // references, which the homing procedure handles.
    if (sample.power_stage_on && sample.state != DriveState::Fault) {
        const InputEdges limits = limit_edges_.update(states);
        if (!sample.homing_mode) {
            const std::uint16_t go = limits.rising & executed;
            reaction.negative_limit_error =
                (go & function_bit(InputFunction::NegativeLimitSwitch)) != 0;
            reaction.positive_limit_error =
                (go & function_bit(InputFunction::PositiveLimitSwitch)) != 0;
        }
    }

    // Table 8-86: "Quickstop" and "Device enable" (enables on its rising edge, disables on its
    // falling edge), each when executed.
    const InputEdges edges = device_edges_.update(states);
    const std::uint16_t enable = function_bit(InputFunction::DeviceEnable) & executed;
    const std::uint16_t quick_stop = function_bit(InputFunction::QuickStop) & executed;
    if ((edges.falling & enable) != 0) {
        reaction.device_commands = kDisableVoltage;
    } else if ((edges.rising & quick_stop) != 0) {
        reaction.device_commands = kQuickStop;
    } else if ((edges.rising & enable) != 0) {
        reaction.device_commands = kEnable;
    }

    // 8.2.58 / 8.2.61: a homing sequence starting resets the marker and disables the compare.
    if (sample.homing_in_progress && !homing_before_) {
        marker_.homing_started();
        const auto configuration = od_.get_as<std::uint16_t>(0x207A, 1);
        od_.set_as(0x207A, 1, static_cast<std::uint16_t>(configuration & ~1U));
    }
    homing_before_ = sample.homing_in_progress;
    marker_.set_homing(sample.homing_in_progress);
    const auto marker = function_bit(InputFunction::PositionMarker);
    reaction.stop = marker_.update((states & marker) != 0, (executed & marker) != 0,
                                   static_cast<std::int32_t>(sample.position));
    store_marker();

    const bool compare =
        compare_.update(sample.now, position_before_.value_or(sample.position), sample.position);
    position_before_ = sample.position;

    std::uint16_t firmware = 0;
    if (device_ready(sample.state)) {
        firmware |= function_bit(OutputFunction::ReadyFault);
    }
    if (compare) {
        firmware |= function_bit(OutputFunction::PositionCompare);
    }
    if (brake_.engaged()) {
        firmware |= function_bit(OutputFunction::HoldingBrake);
    }
    if (firmware != firmware_outputs_) {
        store_firmware_outputs(firmware);
    }
    outputs_.update(static_cast<std::uint16_t>(general_purpose_outputs_ | firmware));
    return reaction;
}

bool Epos2Io::input(unsigned input, const plant::SwitchStates& machine) const {
    if (input < 1 || input > kDigitalInputCount) {
        throw std::invalid_argument("EPOS2 24/5 digital input " + std::to_string(input) +
                                    " does not exist (1 … 6)");
    }
    return (inputs_.levels(machine) & (1U << (input - 1))) != 0;
}

bool Epos2Io::output(unsigned output) const {
    if (output < 1 || output > kDigitalOutputCount) {
        throw std::invalid_argument("EPOS2 24/5 digital output " + std::to_string(output) +
                                    " does not exist (1 … 4)");
    }
    return (outputs_.levels() & (1U << (output - 1))) != 0;
}

} // namespace eposp::drives::epos2
