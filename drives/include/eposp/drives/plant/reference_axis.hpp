#pragma once

#include "eposp/drives/plant/servo_axis.hpp"

namespace eposp::drives::plant {

/// A 20 W brushed motor of maxon's RE 25 size: L/R ≈ 0.11 ms, about one current-loop period.
MotorParameters reference_dc_motor();

/// The reference motor with a small load and gains tuned for it (current loop ~800 Hz, velocity
/// 30 Hz, position 15 Hz), given in the dictionary's integer units, on a 500-pulse encoder: what
/// a simulated drive runs when nothing else is configured, and what the tests move.
AxisParameters reference_axis();

} // namespace eposp::drives::plant
