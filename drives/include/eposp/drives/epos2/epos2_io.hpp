#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/drives/epos2/digital_inputs.hpp"
#include "eposp/drives/epos2/digital_outputs.hpp"
#include "eposp/drives/epos2/holding_brake.hpp"
#include "eposp/drives/epos2/position_compare.hpp"
#include "eposp/drives/epos2/position_marker.hpp"
#include "eposp/drives/motion/device_control.hpp"
#include "eposp/drives/plant/shaft_sensors.hpp"

#include <cstdint>
#include <optional>
#include <span>

namespace eposp::drives::epos2 {

/// What the drive tells its I/O in each control period.
struct IoSample {
    double now = 0;
    std::int64_t position = 0; ///< Position Actual Value
    motion::DriveState state = motion::DriveState::Start;
    bool power_stage_on = false;
    bool homing_mode = false; ///< 0x6061 = 6: the switches are references, not limits
    bool homing_in_progress = false;
    plant::SwitchStates machine_switches{}; ///< the machine's switches at the axis' position
};

/// What the executed inputs ask of the drive (8.2.57, table 8-89).
struct IoReaction {
    bool negative_limit_error = false; ///< 0xFF06 (4.2.27)
    bool positive_limit_error = false; ///< 0xFF07 (4.2.28)
    /// Device commands of the quickstop and device enable inputs: controlword bits 0 … 3 and 7
    /// (table 3-6) to apply in this order.
    std::span<const std::uint16_t> device_commands;
    bool stop = false; ///< position marker Single & Stop: stop with the slow-down ramp (Halt)
};

/// The EPOS2's digital inputs and outputs, position marker, position compare and holding brake
/// (EPOS2 FW spec 6.3, 6.4, 8.2.56 - 8.2.61, 8.2.72, 8.2.73) on the drive's dictionary: reads their
/// configuration when it is written, stores 0x2074 and the firmware's bits of 0x2078 sub 1 when
/// they change. Neither copyable nor movable: the dictionary's listeners refer to it.
class Epos2Io {
public:
    explicit Epos2Io(canopen::ObjectDictionary& od);
    Epos2Io(const Epos2Io&) = delete;
    Epos2Io& operator=(const Epos2Io&) = delete;

    /// Reads every configuration object again (a reset restored them without telling anyone).
    void reload();

    /// One control period, after the plant moved: inputs, their execution, marker, compare,
    /// outputs.
    IoReaction update(const IoSample& sample);
    /// The power stage as the holding brake lets it follow the device control (8.2.72).
    bool power_stage(double now, bool requested, bool fault, double velocity_averaged);
    /// Whether Measure Init may end: the brake has let go for its fall time.
    bool operation_may_start(double now) const { return brake_.operation_may_start(now); }

    void set_input(unsigned input, bool high) { inputs_.set_level(input, high); }
    void hold_limit_switch(InputFunction which, bool pressed) {
        inputs_.hold_limit_switch(which, pressed);
    }
    /// Input n's level (1 … 6) with the machine's switches as `machine` says.
    bool input(unsigned input, const plant::SwitchStates& machine) const;
    /// Output n's level (1 … 4).
    bool output(unsigned output) const;
    /// 0x2071 sub 1.
    std::uint16_t displayed_inputs(const plant::SwitchStates& machine) const {
        return inputs_.displayed(machine);
    }
    /// The limit and home switch functionalities (polarity applied, not masked): homing's view.
    /// Inline: the mode reads it twice each control period.
    plant::SwitchStates switch_functions(const plant::SwitchStates& machine) const {
        const std::uint16_t states = inputs_.states(machine);
        return {.negative_limit = (states & function_bit(InputFunction::NegativeLimitSwitch)) != 0,
                .positive_limit = (states & function_bit(InputFunction::PositiveLimitSwitch)) != 0,
                .home = (states & function_bit(InputFunction::HomeSwitch)) != 0};
    }

private:
    void read_inputs();
    void read_outputs();
    void read_marker();
    void read_compare();
    void read_brake();
    void outputs_written();
    void counter_written();
    void store_marker();
    void store_firmware_outputs(std::uint16_t bits);
    void guard_brake_output();

    canopen::ObjectDictionary& od_;
    DigitalInputs inputs_;
    DigitalOutputs outputs_;
    PositionMarker marker_;
    PositionCompare compare_;
    HoldingBrake brake_;
    EdgeDetector limit_edges_;  ///< sampled while the power stage is on, outside Fault
    EdgeDetector device_edges_; ///< quickstop and device enable, every period
    bool homing_before_ = false;
    bool power_stage_on_ = false;
    std::optional<std::int64_t> position_before_; ///< none before the first period
    std::uint16_t general_purpose_outputs_ = 0;   ///< 0x2078 sub 1, bits 8 … 15
    std::uint16_t firmware_outputs_ = 0;          ///< 0x2078 sub 1, bits 0 … 7
    struct MarkerValues {
        std::int32_t captured, history1, history2;
        std::uint16_t counter;
        friend bool operator==(const MarkerValues&, const MarkerValues&) = default;
    };
    MarkerValues marker_stored_{};
};

/// 0x2101 (8.2.73).
motion::StandstillWindow standstill_window(const canopen::ObjectDictionary& od);

} // namespace eposp::drives::epos2
