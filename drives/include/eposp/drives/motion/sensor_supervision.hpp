#pragma once

#include "eposp/drives/plant/shaft_sensors.hpp"

#include <cstdint>
#include <optional>

namespace eposp::drives::motion {

/// What a position sensor supervision finds; each drive raises its own error code for it (the
/// EPOS2's table 4-11, the ESCON2's table 110).
enum class SensorFault {
    EncoderBreach,      ///< the hardware supervision sees a broken encoder line
    IndexNotFound,      ///< no index within two turns from start-up (encoder with index)
    EncoderResolution,  ///< the counts between the first two index pulses are not 4 × the pulses
    HallSensorNotFound, ///< no hall sensor 3 edge within the first motor turn
    HallSignal,         ///< an impossible hall combination (000, 111) once the sensors were found
    HallAngle,          ///< the encoder's electrical angle left the hall sensors' sector
};

/// A drive's error code for each fault (EPOS2 table 4-11, ESCON2 table 110).
struct SensorErrorCodes {
    std::uint16_t encoder_breach = 0;
    std::uint16_t index_not_found = 0;
    std::uint16_t encoder_resolution = 0;
    std::uint16_t hall_sensor_not_found = 0;
    std::uint16_t hall_signal = 0;
    std::uint16_t hall_angle = 0;

    std::uint16_t of(SensorFault fault) const;
};

/// What the supervision checks, from the drive's sensor configuration.
struct SensorSupervisionConfig {
    int encoder_pulses = 500;       ///< the configured lines per turn (EPOS2 0x2210, ESCON2 0x3010)
    bool encoder = true;            ///< an incremental encoder on the motor shaft
    bool encoder_index = true;      ///< … with index
    bool hall_sensors = false;      ///< the motor's hall sensors
    bool breach_supervision = true; ///< the encoder lines are watched for a breach
    /// The encoder's angle is compared with the hall sensors' (both configured).
    bool hall_angle = false;
    int pole_pairs = 1; ///< electrical revolutions per turn, for the hall angle
    /// Motor turns per encoder turn: an encoder on a gear's output (EPOS2 8.2.74) turns slower.
    double motor_turns_per_encoder_turn = 1;
};

/// A drive's position sensor supervision, fed every control period with the shaft's angle and
/// the injected sensor faults; it reads the sensors as the drive's inputs would and finds (the
/// EPOS2 FW spec 4.2.23 - 4.2.31 and ESCON2 FW spec 7.1.22 - 7.1.24 describe them):
/// - EncoderBreach: a broken encoder line (breach_supervision);
/// - IndexNotFound: no index within two turns from start-up (encoder with index);
/// - EncoderResolution: the counts between the first two index pulses are not 4 × the
///   configured pulses;
/// - HallSensorNotFound: no hall sensor 3 edge within the first motor turn;
/// - HallSignal: an impossible hall combination (000, 111) once the hall sensor 3 edge was found;
/// - HallAngle (hall_angle): from then on, the encoder's electrical angle (counts × pole pairs)
///   strays more than 30° from the sector the hall sensors show. Where the sectors begin on the
///   encoder's scale is not known (the sensors' mounting): every reading bounds it, and a reading
///   that contradicts the earlier ones by more than 30° is the error (a wrong encoder resolution
///   or pole pair setting, a broken encoder or hall wiring). ESCON2 FW spec 7.1.24 gives no
///   threshold: 30° is half a sector, far above the counts' quantisation.
/// Start-up is power-up, a reconfiguration, and the clearing of an error (as the drive decides);
/// a fault found is reported once until the next start-up.
class SensorSupervision {
public:
    void configure(const SensorSupervisionConfig& config) { config_ = config; }
    /// Start-up: the searches for the index and the hall sensor 3 edge begin at `motor_angle`.
    void restart(double motor_angle, std::uint8_t hall_pattern, const plant::SensorFaults& faults);
    std::optional<SensorFault> update(double motor_angle, std::uint8_t hall_pattern,
                                      const plant::SensorFaults& faults);

private:
    /// Where the hall sectors may begin on the encoder's electrical scale, in sectors (60°).
    struct HallOffset {
        double low = 0;
        double high = 0;
    };

    std::int64_t encoder_count(double motor_angle, const plant::SensorFaults& faults) const;
    std::optional<SensorFault> check_encoder(std::int64_t count, std::int64_t travelled,
                                             const plant::SensorFaults& faults);
    std::optional<SensorFault> check_hall_sensors(std::uint8_t inputs, std::int64_t count,
                                                  std::int64_t travelled);
    std::optional<SensorFault> check_hall_angle(std::int64_t count, int sector);

    SensorSupervisionConfig config_;
    bool fault_found_ = false;
    std::int64_t count_ = 0;     ///< the encoder's last reading
    std::int64_t travelled_ = 0; ///< counts moved either way since start-up
    std::optional<std::int64_t> first_index_;
    bool resolution_checked_ = false;
    std::uint8_t hall_inputs_ = 0;
    bool hall_edge_found_ = false;
    std::optional<HallOffset> hall_offset_;
};

} // namespace eposp::drives::motion
