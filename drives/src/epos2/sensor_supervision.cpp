#include "sensor_supervision.hpp"

#include <algorithm>
#include <cstdlib>

namespace eposp::drives::epos2 {
namespace {

// Table 4-11.
constexpr std::uint16_t kHallSensorError = 0xFF01;
constexpr std::uint16_t kIndexProcessingError = 0xFF02;
constexpr std::uint16_t kEncoderResolutionError = 0xFF03;
constexpr std::uint16_t kHallSensorNotFoundError = 0xFF04;
constexpr std::uint16_t kPositionSensorBreachError = 0xFF0A;

constexpr std::uint8_t kHallSensor3 = 0b100;

std::int64_t floor_div(std::int64_t value, std::int64_t divisor) {
    const std::int64_t quotient = value / divisor;
    return (value % divisor != 0 && value < 0) ? quotient - 1 : quotient;
}

} // namespace

void SensorSupervision::restart(double motor_angle, std::uint8_t hall_pattern,
                                const plant::SensorFaults& faults) {
    error_found_ = false;
    count_ = encoder_count(motor_angle, faults);
    travelled_ = 0;
    first_index_.reset();
    resolution_checked_ = false;
    hall_inputs_ = plant::hall_inputs(hall_pattern, faults);
    hall_edge_found_ = false;
}

// A broken encoder counts nothing; a mounted encoder of other lines than configured counts its own.
std::int64_t SensorSupervision::encoder_count(double motor_angle,
                                              const plant::SensorFaults& faults) const {
    if (faults.encoder_broken) {
        return count_;
    }
    return plant::quadcounts(motor_angle, faults.encoder_pulses.value_or(config_.encoder_pulses));
}

std::optional<std::uint16_t> SensorSupervision::update(double motor_angle,
                                                       std::uint8_t hall_pattern,
                                                       const plant::SensorFaults& faults) {
    if (error_found_) {
        return std::nullopt;
    }
    const std::int64_t count = encoder_count(motor_angle, faults);
    // The distance moved as the drive counts it: a turn is 4 × 0x2210 sub 1 of the encoder's
    // counts, whatever the encoder mounted (4.2.26: "encoder resolution too low").
    travelled_ += std::abs(count - count_);
    std::optional<std::uint16_t> error;
    if (config_.encoder) {
        error = check_encoder(count, travelled_, faults);
    }
    count_ = count;
    if (!error && config_.hall_sensors) {
        error = check_hall_sensors(plant::hall_inputs(hall_pattern, faults), travelled_);
    }
    error_found_ = error.has_value();
    return error;
}

std::optional<std::uint16_t> SensorSupervision::check_encoder(std::int64_t count,
                                                              std::int64_t travelled,
                                                              const plant::SensorFaults& faults) {
    // 4.2.31: the differential channels' supervision (0x2008 bit 1 disables it).
    if (faults.encoder_broken) {
        return config_.hardware_supervision ? std::optional{kPositionSensorBreachError}
                                            : std::nullopt;
    }
    if (!config_.encoder_index || resolution_checked_) {
        return std::nullopt;
    }
    const std::int64_t configured_turn = 4 * std::int64_t{config_.encoder_pulses};
    const std::int64_t turn =
        4 * std::int64_t{faults.encoder_pulses.value_or(config_.encoder_pulses)};
    const std::int64_t before = floor_div(count_, turn);
    const std::int64_t after = floor_div(count, turn);
    if (before != after && !faults.index_missing) {
        // The index sits at the boundary between the two revolutions.
        const std::int64_t index = turn * std::max(before, after);
        if (!first_index_) {
            first_index_ = index;
        } else if (index != *first_index_) {
            // 4.2.25: the pulses between the first two index pulses against the resolution.
            resolution_checked_ = true;
            if (std::abs(index - *first_index_) != configured_turn) {
                return kEncoderResolutionError;
            }
        }
    }
    // 4.2.24: "not found within two turns at start-up".
    if (!first_index_ && travelled > 2 * configured_turn) {
        return kIndexProcessingError;
    }
    return std::nullopt;
}

std::optional<std::uint16_t> SensorSupervision::check_hall_sensors(std::uint8_t inputs,
                                                                   std::int64_t travelled) {
    const std::uint8_t previous = hall_inputs_;
    hall_inputs_ = inputs;
    if (!hall_edge_found_) {
        // 4.2.26: "No Hall sensor 3 edge found within first motor turn".
        hall_edge_found_ = ((previous ^ inputs) & kHallSensor3) != 0;
        if (!hall_edge_found_ && travelled > 4 * std::int64_t{config_.encoder_pulses}) {
            return kHallSensorNotFoundError;
        }
        return std::nullopt;
    }
    // 4.2.23: "an impossible signal combination".
    if (inputs == 0 || inputs == 0b111) {
        return kHallSensorError;
    }
    return std::nullopt;
}

} // namespace eposp::drives::epos2
