#pragma once

#include "eposp/drives/escon2/protection/device_error_code.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace eposp::drives::escon2 {

/// 0x2201 sub 1 / 2 (mV there) and the variant's hysteresis (tables 41 - 44), V; the defaults
/// are the ESCON2 Module 60/30's.
struct SupplyLimits {
    double undervoltage_limit = 7.5;
    double undervoltage_hysteresis = 0.25;
    double overvoltage_limit = 65;
    double overvoltage_hysteresis = 1;
};

/// Why `limits` break 6.2.11's rule ("the undervoltage limit must be lower than overvoltage
/// limit minus overvoltage hysteresis minus undervoltage hysteresis"), or nothing.
std::optional<std::string> supply_limits_error(const SupplyLimits& limits);

/// The power supply supervision (ESCON2 FW spec 6.2.10, 6.2.11, 7.1.6, 7.1.7): the device may
/// be enabled only above the undervoltage limit; below it while enabled is the undervoltage
/// error, present until the supply rises above limit + hysteresis; above the overvoltage limit,
/// enabled or not, the overvoltage error, present until the supply falls below limit −
/// hysteresis. The drive enters the errors and refuses a fault reset while one is present.
class PowerSupplySupervision {
public:
    PowerSupplySupervision() = default;
    explicit PowerSupplySupervision(const SupplyLimits& limits);

    /// New limits, or why they are refused (the old ones stay).
    std::optional<std::string> set_limits(const SupplyLimits& limits);
    /// The supply voltage (V) now, and whether the drive is enabled (operation enabled or quick
    /// stop active).
    void update(double voltage, bool enabled);

    /// 6.2.11.1: "The device can only be enabled if the supply voltage is higher than the
    /// undervoltage limit".
    bool may_enable() const { return voltage_ > limits_.undervoltage_limit; }
    bool undervoltage() const { return undervoltage_; }
    bool overvoltage() const { return overvoltage_; }
    /// The present conditions as error codes (table 110).
    std::vector<DeviceErrorCode> conditions() const;
    /// 0x2200 sub 1: the supply voltage in 0.1 V.
    std::uint16_t voltage_object() const;

private:
    SupplyLimits limits_;
    double voltage_ = 0;
    bool undervoltage_ = false;
    bool overvoltage_ = false;
};

} // namespace eposp::drives::escon2
