#include "diagnostic_mode.hpp"

namespace eposp::drives::epos2 {

// The motion is the actual one: a stop ramp of the device control starts from it.
ModeDemand DiagnosticMode::demand(const ModeInputs& inputs) {
    return {.motion = {static_cast<double>(inputs.position), inputs.velocity, 0},
            .loop = plant::ControlMode::Current,
            .current = 0};
}

} // namespace eposp::drives::epos2
