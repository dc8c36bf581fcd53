#include "eposp/drives/motion/sensor_supervision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace eposp::drives::motion {
namespace {

constexpr std::uint8_t kHallSensor3 = 0b100;
constexpr double kSectorsPerElectricalTurn = 6;
constexpr double kHallAngleTolerance = 0.5; // sectors: 30° electrical

std::int64_t floor_div(std::int64_t value, std::int64_t divisor) {
    const std::int64_t quotient = value / divisor;
    return (value % divisor != 0 && value < 0) ? quotient - 1 : quotient;
}

} // namespace

std::uint16_t SensorErrorCodes::of(SensorFault fault) const {
    switch (fault) {
    case SensorFault::EncoderBreach:
        return encoder_breach;
    case SensorFault::IndexNotFound:
        return index_not_found;
    case SensorFault::EncoderResolution:
        return encoder_resolution;
    case SensorFault::HallSensorNotFound:
        return hall_sensor_not_found;
    case SensorFault::HallSignal:
        return hall_signal;
    case SensorFault::HallAngle:
        return hall_angle;
    }
    return 0; // not reached: every enumerator has its case
}

void SensorSupervision::restart(double motor_angle, std::uint8_t hall_pattern,
                                const plant::SensorFaults& faults) {
    fault_found_ = false;
    count_ = encoder_count(motor_angle, faults);
    travelled_ = 0;
    first_index_.reset();
    resolution_checked_ = false;
    hall_inputs_ = plant::hall_inputs(hall_pattern, faults);
    hall_edge_found_ = false;
    hall_offset_.reset();
}

// A broken encoder counts nothing; a mounted encoder of other lines than configured counts its own.
std::int64_t SensorSupervision::encoder_count(double motor_angle,
                                              const plant::SensorFaults& faults) const {
    if (faults.encoder_silent()) {
        return count_;
    }
    return plant::quadcounts(motor_angle, faults.encoder_pulses.value_or(config_.encoder_pulses));
}

std::optional<SensorFault> SensorSupervision::update(double motor_angle, std::uint8_t hall_pattern,
                                                     const plant::SensorFaults& faults) {
    if (fault_found_) {
        return std::nullopt;
    }
    const std::int64_t count = encoder_count(motor_angle, faults);
    // The distance moved as the drive counts it: a turn is 4 × the configured pulses of the
    // encoder's counts, whatever the encoder mounted (EPOS2 4.2.26: "encoder resolution too low").
    travelled_ += std::abs(count - count_);
    std::optional<SensorFault> fault;
    // Once the index checks are done (or without an index) only a breach is left to find.
    const bool index_checks = config_.encoder_index && !resolution_checked_;
    if (config_.encoder && (index_checks || faults.encoder_silent())) {
        fault = check_encoder(count, travelled_, faults);
    }
    count_ = count;
    if (!fault && config_.hall_sensors) {
        fault = check_hall_sensors(plant::hall_inputs(hall_pattern, faults), count, travelled_);
    }
    fault_found_ = fault.has_value();
    return fault;
}

// Only while a breach can be found or the index checks are pending (update() asks).
std::optional<SensorFault> SensorSupervision::check_encoder(std::int64_t count,
                                                            std::int64_t travelled,
                                                            const plant::SensorFaults& faults) {
    // EPOS2 4.2.31: the differential channels' supervision (0x2008 bit 1 disables it).
    if (faults.encoder_silent()) {
        return config_.breach_supervision ? std::optional{SensorFault::EncoderBreach}
                                          : std::nullopt;
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
            // EPOS2 4.2.25: the pulses between the first two index pulses against the resolution.
            resolution_checked_ = true;
            if (std::abs(index - *first_index_) != configured_turn) {
                return SensorFault::EncoderResolution;
            }
        }
    }
    // EPOS2 4.2.24: "not found within two turns at start-up".
    if (!first_index_ && travelled > 2 * configured_turn) {
        return SensorFault::IndexNotFound;
    }
    return std::nullopt;
}

std::optional<SensorFault> SensorSupervision::check_hall_sensors(std::uint8_t inputs,
                                                                 std::int64_t count,
                                                                 std::int64_t travelled) {
    const std::uint8_t previous = hall_inputs_;
    hall_inputs_ = inputs;
    if (!hall_edge_found_) {
        // EPOS2 4.2.26: "No Hall sensor 3 edge found within first motor turn".
        hall_edge_found_ = ((previous ^ inputs) & kHallSensor3) != 0;
        const double motor_turns = static_cast<double>(travelled) *
                                   config_.motor_turns_per_encoder_turn /
                                   static_cast<double>(4 * std::int64_t{config_.encoder_pulses});
        if (!hall_edge_found_ && motor_turns > 1) {
            return SensorFault::HallSensorNotFound;
        }
        return std::nullopt;
    }
    // EPOS2 4.2.23: "an impossible signal combination".
    const std::optional<int> sector = plant::hall_sector(inputs);
    if (!sector) {
        return SensorFault::HallSignal;
    }
    return config_.hall_angle ? check_hall_angle(count, *sector) : std::nullopt;
}

// ESCON2 7.1.24: "Angle difference measured between the encoder and Hall sensors is too high".
// The hall sector starts at `offset` + the encoder's electrical angle, for an offset that each
// reading bounds to one sector; the readings so far leave [low, high].
std::optional<SensorFault> SensorSupervision::check_hall_angle(std::int64_t count, int sector) {
    const double angle = static_cast<double>(count) * kSectorsPerElectricalTurn *
                         config_.pole_pairs /
                         static_cast<double>(plant::counts_per_turn(config_.encoder_pulses));
    double low = sector - angle;
    if (!hall_offset_) {
        hall_offset_ = HallOffset{.low = low, .high = low + 1};
        return std::nullopt;
    }
    // The same bound an electrical turn away: the one nearest to what is known.
    const double known = (hall_offset_->low + hall_offset_->high) / 2;
    low +=
        kSectorsPerElectricalTurn * std::round((known - (low + 0.5)) / kSectorsPerElectricalTurn);
    const HallOffset narrowed{.low = std::max(hall_offset_->low, low),
                              .high = std::min(hall_offset_->high, low + 1)};
    if (narrowed.low <= narrowed.high) {
        hall_offset_ = narrowed;
        return std::nullopt;
    }
    // A contradiction within the tolerance leaves the bounds as they are, so that a slow drift
    // (a resolution a little off) adds up until it shows.
    return narrowed.low - narrowed.high > kHallAngleTolerance
               ? std::optional{SensorFault::HallAngle}
               : std::nullopt;
}

} // namespace eposp::drives::motion
