#include "eposp/drives/motion/device_control.hpp"

namespace eposp::drives::motion {

namespace {

constexpr std::uint16_t kSwitchOnBit = 1U << 0;
constexpr std::uint16_t kEnableVoltageBit = 1U << 1;
constexpr std::uint16_t kQuickStopBit = 1U << 2;
constexpr std::uint16_t kEnableOperationBit = 1U << 3;
constexpr std::uint16_t kFaultResetBit = 1U << 7;

} // namespace

const char* to_string(DriveState state) {
    switch (state) {
    case DriveState::Start:
        return "Start";
    case DriveState::NotReadyToSwitchOn:
        return "Not Ready to Switch On";
    case DriveState::SwitchOnDisabled:
        return "Switch On Disabled";
    case DriveState::ReadyToSwitchOn:
        return "Ready to Switch On";
    case DriveState::SwitchedOn:
        return "Switched On";
    case DriveState::Refresh:
        return "Refresh";
    case DriveState::MeasureInit:
        return "Measure Init";
    case DriveState::OperationEnable:
        return "Operation Enable";
    case DriveState::QuickStopActive:
        return "Quickstop Active";
    case DriveState::FaultReactionActiveDisabled:
        return "Fault Reaction Active (disabled)";
    case DriveState::FaultReactionActiveEnabled:
        return "Fault Reaction Active (enabled)";
    case DriveState::Fault:
        return "Fault";
    }
    return "?";
}

// EPOS2 FW spec table 3-4, the bits not marked x.
std::uint16_t state_bits(DriveState state) {
    switch (state) {
    case DriveState::Start:
        return 0x0000;
    case DriveState::NotReadyToSwitchOn:
        return 0x0100;
    case DriveState::SwitchOnDisabled:
        return 0x0140;
    case DriveState::ReadyToSwitchOn:
        return 0x0121;
    case DriveState::SwitchedOn:
        return 0x0123;
    case DriveState::Refresh:
        return 0x4123;
    case DriveState::MeasureInit:
        return 0x4133;
    case DriveState::OperationEnable:
        return 0x0137;
    case DriveState::QuickStopActive:
        return 0x0117;
    case DriveState::FaultReactionActiveDisabled:
        return 0x010F;
    case DriveState::FaultReactionActiveEnabled:
        return 0x011F;
    case DriveState::Fault:
        return 0x0108;
    }
    return 0;
}

// EPOS2 FW spec table 3-6, checked from the most dominant bit: Disable Voltage (xx0x) wins over
// Quickstop (x01x), which wins over Shutdown (x110).
DeviceCommand decode_device_command(std::uint16_t controlword) {
    if ((controlword & kEnableVoltageBit) == 0) {
        return DeviceCommand::DisableVoltage;
    }
    if ((controlword & kQuickStopBit) == 0) {
        return DeviceCommand::QuickStop;
    }
    if ((controlword & kSwitchOnBit) == 0) {
        return DeviceCommand::Shutdown;
    }
    if ((controlword & kEnableOperationBit) == 0) {
        return DeviceCommand::SwitchOn;
    }
    return DeviceCommand::EnableOperation;
}

// EPOS2 FW spec 8.2.84 and 8.2.89; "d" errors always disable (4.2.1). Out-of-range codes, which
// the dictionary refuses anyway, take the safest reaction.
FaultReaction fault_reaction(FaultClass fault_class, const OptionCodes& codes) {
    switch (fault_class) {
    case FaultClass::Critical:
        return FaultReaction::DisableDrive;
    case FaultClass::Communication:
        switch (codes.abort_connection) {
        case 1:
            return FaultReaction::SignalOnly;
        case 3:
            return FaultReaction::QuickStop;
        default:
            return FaultReaction::DisableDrive;
        }
    case FaultClass::Device:
        switch (codes.fault_reaction) {
        case -1:
            return FaultReaction::SignalOnly;
        case 1:
            return FaultReaction::SlowDown;
        case 2:
            return FaultReaction::QuickStop;
        default:
            return FaultReaction::DisableDrive;
        }
    }
    return FaultReaction::DisableDrive;
}

std::uint16_t DeviceControl::statusword() const {
    // ESCON2 FW spec table 6: the EPOS2's bits without bit 8 (reserved) and 14 (Refresh).
    constexpr std::uint16_t kEscon2StateBits = 0x007F;
    const std::uint16_t bits =
        machine_ == StateMachine::Escon2
            ? static_cast<std::uint16_t>(state_bits(state_) & kEscon2StateBits)
            : state_bits(state_);
    return static_cast<std::uint16_t>(bits | (warning_ ? kWarningBit : 0U));
}

void DeviceControl::write_controlword(std::uint16_t controlword) {
    if (busy()) {
        has_held_controlword_ = true;
        held_controlword_ = controlword;
        return;
    }
    const bool fault_reset = (controlword & kFaultResetBit) != 0;
    const bool rising_edge = fault_reset && !fault_reset_bit_;
    fault_reset_bit_ = fault_reset;
    if (rising_edge) {
        // Transition 15, only "if no fault is present"; elsewhere the edge clears the warning.
        if (state_ == DriveState::Fault && !fault_condition_present_) {
            enter(DriveState::SwitchOnDisabled);
        }
        if (state_ != DriveState::Fault) {
            warning_ = false;
        }
        return;
    }
    // Table 3-6: every device command has bit 7 cleared.
    if (!fault_reset) {
        apply(decode_device_command(controlword));
    }
}

void DeviceControl::apply(DeviceCommand command) {
    using enum DeviceCommand;
    switch (state_) {
    case DriveState::SwitchOnDisabled:
        if (command == Shutdown) {
            enter(DriveState::ReadyToSwitchOn); // 2
        }
        break;
    case DriveState::ReadyToSwitchOn:
        if (command == SwitchOn) {
            enter(DriveState::SwitchedOn); // 3
        } else if (command == EnableOperation) {
            enter(DriveState::SwitchedOn); // 3, then 4 automatically (table 3-6 remark *1)
            enable_operation();
        } else if (command == DisableVoltage || command == QuickStop) {
            enter(DriveState::SwitchOnDisabled); // 7
        }
        break;
    case DriveState::SwitchedOn:
        if (command == EnableOperation) {
            enable_operation(); // 4
        } else if (command == Shutdown) {
            enter(DriveState::ReadyToSwitchOn); // 6
        } else if (command == DisableVoltage || command == QuickStop) {
            enter(DriveState::SwitchOnDisabled); // 10
        }
        break;
    case DriveState::OperationEnable:
        if (command == SwitchOn) {
            begin_disable(DriveState::SwitchedOn, codes_.disable_operation); // 5
        } else if (command == Shutdown) {
            begin_disable(DriveState::ReadyToSwitchOn, codes_.shutdown); // 8
        } else if (command == DisableVoltage) {
            enter(DriveState::SwitchOnDisabled); // 9
        } else if (command == QuickStop) {
            enter(DriveState::QuickStopActive); // 11
        }
        break;
    case DriveState::QuickStopActive:
        if (command == DisableVoltage) {
            enter(DriveState::SwitchOnDisabled); // 12
        } else if (command == EnableOperation) {
            enter(DriveState::OperationEnable); // 16
        }
        break;
    default:
        break;
    }
}

// EPOS2 FW spec 8.2.87/8.2.88: option code 1 slows down first, 0 switches the power stage off.
void DeviceControl::begin_disable(DriveState target, std::int16_t option_code) {
    if (option_code == 1) {
        slowing_down_ = true;
        slow_down_target_ = target;
    } else {
        enter(target);
    }
}

// EPOS2 FW spec table 3-5: transition 4 refreshes the power stage and measures; ESCON2 FW spec
// table 7: it enables the drive function at once.
void DeviceControl::enable_operation() {
    enter(machine_ == StateMachine::Escon2 ? DriveState::OperationEnable : DriveState::Refresh);
}

void DeviceControl::node_reset() {
    enter(DriveState::Start); // 19
    warning_ = false;
    fault_reset_bit_ = false;
}

void DeviceControl::initialise() {
    if (state_ == DriveState::Start) {
        enter(DriveState::NotReadyToSwitchOn); // 0
    }
}

void DeviceControl::initialisation_finished() {
    if (state_ == DriveState::NotReadyToSwitchOn) {
        enter(DriveState::SwitchOnDisabled); // 1
    }
}

void DeviceControl::refresh_finished() {
    if (state_ == DriveState::Refresh) {
        enter(DriveState::MeasureInit); // 20
    }
}

void DeviceControl::measure_init_finished() {
    if (state_ == DriveState::MeasureInit) {
        enter(DriveState::OperationEnable); // 21
        finish_pending_transition();
    }
}

void DeviceControl::stop_completed() {
    if (slowing_down_) {
        slowing_down_ = false;
        enter(slow_down_target_); // 5 or 8, after the ramp
        finish_pending_transition();
    } else if (state_ == DriveState::FaultReactionActiveDisabled ||
               state_ == DriveState::FaultReactionActiveEnabled) {
        enter(DriveState::Fault); // 14, 18
    }
}

void DeviceControl::fault_occurred(FaultClass fault_class) {
    const FaultReaction reaction = fault_reaction(fault_class, codes_);
    if (reaction == FaultReaction::SignalOnly) {
        warning_ = true; // 8.2.84, 8.2.89: EMCY and warning bit, no state change
        return;
    }
    switch (state_) {
    case DriveState::Fault:
    case DriveState::FaultReactionActiveDisabled:
    case DriveState::FaultReactionActiveEnabled:
        return;
    case DriveState::OperationEnable:
    case DriveState::QuickStopActive:
        reaction_ = reaction;
        enter(DriveState::FaultReactionActiveEnabled); // 17
        break;
    default:
        reaction_ = FaultReaction::DisableDrive;
        enter(DriveState::FaultReactionActiveDisabled); // 13
        break;
    }
    // A fault overrides whatever transition was under way.
    slowing_down_ = false;
    has_held_controlword_ = false;
}

void DeviceControl::finish_pending_transition() {
    if (has_held_controlword_) {
        has_held_controlword_ = false;
        write_controlword(held_controlword_);
    }
}

void DeviceControl::enter(DriveState state) {
    state_ = state;
}

bool DeviceControl::busy() const {
    return slowing_down_ || state_ == DriveState::Refresh || state_ == DriveState::MeasureInit;
}

} // namespace eposp::drives::motion
