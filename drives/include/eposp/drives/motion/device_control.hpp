#pragma once

#include <cstdint>

namespace eposp::drives::motion {

/// EPOS2 FW spec 3.2.1, table 3-4: the states of the drive, including maxon's Refresh and
/// Measure Init between Switched On and Operation Enable.
enum class DriveState {
    Start,
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    Refresh,
    MeasureInit,
    OperationEnable,
    QuickStopActive,
    FaultReactionActiveDisabled,
    FaultReactionActiveEnabled,
    Fault,
};

const char* to_string(DriveState state);

/// EPOS2 FW spec 8.2.86: the statusword bits that encode the state (0…6, 8 and 14).
inline constexpr std::uint16_t kStateBitsMask = 0x417F;
inline constexpr std::uint16_t kWarningBit = 1U << 7;

/// EPOS2 FW spec table 3-4: the statusword bits (under kStateBitsMask) of a state.
std::uint16_t state_bits(DriveState state);

/// EPOS2 FW spec table 3-6: the commands encoded in controlword bits 0…3 (bit 7 is Fault Reset,
/// handled on its rising edge). Switch On and Disable Operation share one pattern (0111), as do
/// Enable Operation and Switch On & Enable Operation (1111); the state tells them apart.
enum class DeviceCommand { Shutdown, SwitchOn, DisableVoltage, QuickStop, EnableOperation };

DeviceCommand decode_device_command(std::uint16_t controlword);

/// EPOS2 FW spec 4.2.1: which option code decides the reaction to an error.
enum class FaultClass {
    Device,        ///< "f": Fault Reaction Option Code 0x605E
    Communication, ///< "a": Abort Connection Option Code 0x6007
    Critical,      ///< "d": secure movement no longer possible, always disables
};

/// The option codes as written in the dictionary; defaults are the spec's (8.2.84, 8.2.87-89).
struct OptionCodes {
    std::int16_t abort_connection = 3;  ///< 0x6007: 1 signal only, 2 disable voltage, 3 quickstop
    std::int16_t shutdown = 0;          ///< 0x605B: 0 disable, 1 slow down then disable
    std::int16_t disable_operation = 1; ///< 0x605C: 0 disable, 1 slow down then disable
    std::int16_t fault_reaction =
        2; ///< 0x605E: -1 signal only, 0 disable, 1 slow down, 2 quickstop
};

/// How motion is brought to rest when the drive function is being left.
enum class StopRamp {
    None,      ///< the operating mode runs (or nothing is powered)
    SlowDown,  ///< the deceleration of the mode of operation (8.2.87)
    QuickStop, ///< Quickstop Deceleration 0x6085
};

/// The reaction an error calls for, decided from its class and the option codes.
enum class FaultReaction { SignalOnly, DisableDrive, SlowDown, QuickStop };

FaultReaction fault_reaction(FaultClass fault_class, const OptionCodes& codes);

/// What the power stage and the motion layer must do in the present state.
struct DriveOutputs {
    bool power_stage_on = false;         ///< PWM enabled, current flows (statusword bit 4)
    bool drive_function_enabled = false; ///< the mode's trajectory drives the controllers
    StopRamp ramp = StopRamp::None;      ///< a stop in progress, overriding the mode's trajectory

    friend bool operator==(const DriveOutputs&, const DriveOutputs&) = default;
};

/// Whose state machine: the EPOS2's (FW spec 3.2) passes Refresh and Measure Init between
/// Switched On and Operation Enable and sets statusword bit 8; the ESCON2's (FW spec 2.2, tables
/// 6 - 8) calibrates the current offset in transition 3, enables at once in transition 4, and
/// keeps bit 8 reserved (0), so that its states show only bits 0 - 6.
enum class StateMachine { Epos2, Escon2 };

/// The CiA 402 device control state machine of the EPOS2 (FW spec 3.2, tables 3-4 to 3-6). It is
/// fed with controlword writes and internal events and has no clock of its own: the drive reports
/// when a refresh, a measurement or a stop has finished. A command that starts a transition which
/// takes time (Refresh, Measure Init, a slow-down ramp) is processed completely before the next
/// one (3.2.2 note): controlwords written meanwhile are held and the last one applied afterwards.
class DeviceControl {
public:
    explicit DeviceControl(OptionCodes codes = {}, StateMachine machine = StateMachine::Epos2)
        : codes_(codes), machine_(machine) {}

    DriveState state() const { return state_; }
    /// Bits 0…8 and 14 of the statusword; mode-specific bits are the operating mode's.
    std::uint16_t statusword() const;
    /// Inline: a drive asks several times each control period.
    DriveOutputs outputs() const {
        switch (state_) {
        case DriveState::MeasureInit:
            return {true, false, StopRamp::None};
        case DriveState::OperationEnable:
            return {true, true, slowing_down_ ? StopRamp::SlowDown : StopRamp::None};
        case DriveState::QuickStopActive:
            return {true, true, StopRamp::QuickStop};
        case DriveState::FaultReactionActiveEnabled:
            switch (reaction_) {
            case FaultReaction::SlowDown:
                return {true, true, StopRamp::SlowDown};
            case FaultReaction::QuickStop:
                return {true, true, StopRamp::QuickStop};
            case FaultReaction::SignalOnly:
            case FaultReaction::DisableDrive:
                break;
            }
            return {};
        default:
            return {};
        }
    }

    void set_option_codes(const OptionCodes& codes) { codes_ = codes; }

    /// Controlword 0x6040 written (bits 0…3 and 7; table 3-6).
    void write_controlword(std::uint16_t controlword);

    /// Transition 19: NMT Reset Node; also the power-on state.
    void node_reset();
    /// Transition 0: initialisation starts (current offset measurement).
    void initialise();
    /// Transition 1: initialisation finished, communication active.
    void initialisation_finished();
    /// Transition 20: the refresh cycle of the power stage finished.
    void refresh_finished();
    /// Transition 21: the Measure Init cycle finished.
    void measure_init_finished();
    /// A stop requested through outputs() (ramp or power-off) has finished: completes a
    /// slowed-down disable (5, 8) and the fault reaction (14, 18).
    void stop_completed();

    /// Transitions 13 and 17: an error occurred; its reaction follows the option codes. A
    /// "signal only" reaction only sets the warning bit.
    void fault_occurred(FaultClass fault_class);
    /// Whether an error condition persists (e.g. undervoltage); Fault Reset (15) is refused while
    /// it does.
    void set_fault_condition_present(bool present) { fault_condition_present_ = present; }

private:
    void apply(DeviceCommand command);
    void begin_disable(DriveState target, std::int16_t option_code);
    void finish_pending_transition();
    void enter(DriveState state);
    bool busy() const;

    /// Transition 4 (and 3, 4 of "Switch on & Enable operation").
    void enable_operation();

    OptionCodes codes_;
    StateMachine machine_;
    DriveState state_ = DriveState::Start;
    bool warning_ = false;
    bool fault_reset_bit_ = false;
    bool fault_condition_present_ = false;
    FaultReaction reaction_ = FaultReaction::DisableDrive;
    // A slowed-down disable in progress (transitions 5 and 8 with option code 1).
    bool slowing_down_ = false;
    DriveState slow_down_target_ = DriveState::SwitchedOn;
    // The last controlword written while a transition was in progress.
    bool has_held_controlword_ = false;
    std::uint16_t held_controlword_ = 0;
};

} // namespace eposp::drives::motion
