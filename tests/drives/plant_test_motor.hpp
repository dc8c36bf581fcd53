#pragma once

#include "eposp/drives/plant/reference_axis.hpp"
#include "eposp/drives/plant/servo_axis.hpp"

namespace eposp::drives::plant::test {

/// The reference motor without load or gearhead.
inline PlantParameters free_motor() {
    PlantParameters plant;
    plant.motor = reference_dc_motor();
    return plant;
}

inline AxisParameters tuned_axis() {
    return reference_axis();
}

} // namespace eposp::drives::plant::test
