#include "eposp/drives/escon2/protection/power_supply_supervision.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace eposp::drives::escon2 {

std::optional<std::string> supply_limits_error(const SupplyLimits& limits) {
    const double highest_undervoltage_limit =
        limits.overvoltage_limit - limits.overvoltage_hysteresis - limits.undervoltage_hysteresis;
    if (!(limits.undervoltage_limit < highest_undervoltage_limit)) {
        return "the undervoltage limit (" + std::to_string(limits.undervoltage_limit) +
               " V) must be lower than the overvoltage limit minus both hysteresis (" +
               std::to_string(highest_undervoltage_limit) + " V)";
    }
    return std::nullopt;
}

PowerSupplySupervision::PowerSupplySupervision(const SupplyLimits& limits) {
    if (std::optional<std::string> error = set_limits(limits)) {
        throw std::invalid_argument(*error);
    }
}

std::optional<std::string> PowerSupplySupervision::set_limits(const SupplyLimits& limits) {
    if (std::optional<std::string> error = supply_limits_error(limits)) {
        return error;
    }
    limits_ = limits;
    return std::nullopt;
}

void PowerSupplySupervision::update(double voltage, bool enabled) {
    voltage_ = voltage;
    if (voltage > limits_.overvoltage_limit) {
        overvoltage_ = true;
    } else if (voltage < limits_.overvoltage_limit - limits_.overvoltage_hysteresis) {
        overvoltage_ = false;
    }
    if (enabled && voltage < limits_.undervoltage_limit) {
        undervoltage_ = true;
    } else if (voltage > limits_.undervoltage_limit + limits_.undervoltage_hysteresis) {
        undervoltage_ = false;
    }
}

std::vector<DeviceErrorCode> PowerSupplySupervision::conditions() const {
    std::vector<DeviceErrorCode> codes;
    if (overvoltage_) {
        codes.push_back(DeviceErrorCode::Overvoltage);
    }
    if (undervoltage_) {
        codes.push_back(DeviceErrorCode::Undervoltage);
    }
    return codes;
}

std::uint16_t PowerSupplySupervision::voltage_object() const {
    return static_cast<std::uint16_t>(std::clamp(std::lround(voltage_ * 10), 0L, 0xFFFFL));
}

} // namespace eposp::drives::escon2
