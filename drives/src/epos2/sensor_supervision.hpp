#pragma once

#include "eposp/drives/plant/shaft_sensors.hpp"

#include <cstdint>
#include <optional>

namespace eposp::drives::epos2 {

/// What the sensor supervision checks, from 0x2210, 0x6402 and 0x2008.
struct SensorSupervisionConfig {
    int encoder_pulses = 500;         ///< 0x2210 sub 1
    bool encoder = true;              ///< main sensor Incremental Encoder 1 (table 8-102: 1 or 2)
    bool encoder_index = true;        ///< … with index (type 1)
    bool hall_sensors = false;        ///< an EC motor (table 8-125: 10, 11) has hall sensors
    bool hardware_supervision = true; ///< 0x2008 bit 1 clear (8.2.41)
};

/// The EPOS2's position sensor supervision (EPOS2 FW spec 4.2.23 - 4.2.31), fed every control
/// period with the shaft's angle and the injected sensor faults; it reads the sensors as the
/// drive's inputs would and finds:
/// - 0xFF0A Position Sensor Breach: the hardware supervision sees a broken encoder line;
/// - 0xFF02 Index Processing: no index within two turns from start-up (encoder with index);
/// - 0xFF03 Encoder Resolution: the counts between the first two index pulses are not 4 × 0x2210
///   sub 1;
/// - 0xFF04 Hall Sensor not found: no hall sensor 3 edge within the first motor turn;
/// - 0xFF01 Hall Sensor Error: an impossible hall combination (000, 111) once the hall sensor 3
///   edge was found.
/// Start-up is power-up, a reconfiguration, and the clearing of an error with position reset; an
/// error found is reported once until the next start-up.
class SensorSupervision {
public:
    void configure(const SensorSupervisionConfig& config) { config_ = config; }
    /// Start-up: the searches for the index and the hall sensor 3 edge begin at `motor_angle`.
    void restart(double motor_angle, std::uint8_t hall_pattern, const plant::SensorFaults& faults);
    std::optional<std::uint16_t> update(double motor_angle, std::uint8_t hall_pattern,
                                        const plant::SensorFaults& faults);

private:
    std::int64_t encoder_count(double motor_angle, const plant::SensorFaults& faults) const;
    std::optional<std::uint16_t> check_encoder(std::int64_t count, std::int64_t travelled,
                                               const plant::SensorFaults& faults);
    std::optional<std::uint16_t> check_hall_sensors(std::uint8_t inputs, std::int64_t travelled);

    SensorSupervisionConfig config_;
    bool error_found_ = false;
    std::int64_t count_ = 0;     ///< the encoder's last reading
    std::int64_t travelled_ = 0; ///< counts moved either way since start-up
    std::optional<std::int64_t> first_index_;
    bool resolution_checked_ = false;
    std::uint8_t hall_inputs_ = 0;
    bool hall_edge_found_ = false;
};

} // namespace eposp::drives::epos2
