#include "mode_table.hpp"

#include "current_mode.hpp"
#include "diagnostic_mode.hpp"
#include "digital_position_mode.hpp"
#include "homing_mode.hpp"
#include "interpolated_position_mode.hpp"
#include "position_mode.hpp"
#include "profile_position_mode.hpp"
#include "profile_velocity_mode.hpp"
#include "velocity_mode.hpp"

namespace eposp::drives::epos2 {

std::optional<OperatingMode> simulated_mode(std::int8_t modes_of_operation) {
    switch (static_cast<OperatingMode>(modes_of_operation)) {
    case OperatingMode::ProfilePosition:
    case OperatingMode::ProfileVelocity:
    case OperatingMode::Homing:
    case OperatingMode::Position:
    case OperatingMode::Velocity:
    case OperatingMode::Current:
    case OperatingMode::Diagnostic:
    case OperatingMode::InterpolatedPosition:
    case OperatingMode::MasterEncoder:
    case OperatingMode::StepDirection:
        return static_cast<OperatingMode>(modes_of_operation);
    }
    return std::nullopt;
}

std::unique_ptr<ModeBehaviour> make_mode_behaviour(OperatingMode mode, ModeServices& services) {
    switch (mode) {
    case OperatingMode::ProfilePosition:
        return std::make_unique<ProfilePositionMode>(services);
    case OperatingMode::ProfileVelocity:
        return std::make_unique<ProfileVelocityMode>(services);
    case OperatingMode::Homing:
        return std::make_unique<HomingMode>(services);
    case OperatingMode::Position:
        return std::make_unique<PositionMode>(services);
    case OperatingMode::Velocity:
        return std::make_unique<VelocityMode>(services);
    case OperatingMode::Current:
        return std::make_unique<CurrentMode>(services);
    case OperatingMode::Diagnostic:
        return std::make_unique<DiagnosticMode>();
    case OperatingMode::InterpolatedPosition:
        return std::make_unique<InterpolatedPositionMode>(services);
    case OperatingMode::MasterEncoder:
    case OperatingMode::StepDirection:
        return std::make_unique<DigitalPositionMode>(services);
    }
    return std::make_unique<ProfilePositionMode>(services);
}

} // namespace eposp::drives::epos2
