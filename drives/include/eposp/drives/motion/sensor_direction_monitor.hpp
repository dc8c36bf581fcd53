#pragma once

#include <cstdint>

namespace eposp::drives::motion {

/// The direction check of the software position sensor supervision (EPOS2 FW spec 4.2.37, Main
/// Sensor Direction Error: "a turn away of the motor in the opposite direction due to wrong
/// setting of sensor polarity, wrong position sensor wiring, wrong motor wiring"). The drive
/// knows which way the motor turns from its terminals (8.2.41 bit 2: the motor resistance it
/// measures serves this supervision: the back-EMF is U − R·I) and compares that with the main
/// sensor's counts. The sensor counting against the motor for `limit` counts in a row is the
/// error; where the motor reverses the two disagree for a count or two only.
class SensorDirectionMonitor {
public:
    /// Starts at the sensor's `position`.
    explicit SensorDirectionMonitor(std::int64_t limit = 500, std::int64_t position = 0)
        : limit_(limit), position_(position) {}

    /// Each control period: `motor_speed` the motor's as its terminals show it (only its sign
    /// counts; 0 with the power stage off or the supervision disabled: nothing to compare),
    /// `position` the sensor's counts as the drive reads them. True while the sensor has counted
    /// `limit` or more against the motor.
    bool update(double motor_speed, std::int64_t position);

private:
    std::int64_t limit_;
    std::int64_t position_;
    std::int64_t against_ = 0; ///< counts against the motor since they last agreed
};

} // namespace eposp::drives::motion
