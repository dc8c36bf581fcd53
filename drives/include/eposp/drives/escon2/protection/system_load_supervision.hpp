#pragma once

#include "eposp/drives/escon2/protection/device_error_code.hpp"
#include "eposp/drives/motion/system_load.hpp"

#include <vector>

namespace eposp::drives::escon2 {

/// The system load supervision (ESCON2 FW spec 7.1.36 - 7.1.40) of the load set from outside
/// (motion::SystemLoad). The manual gives no thresholds; the simulation's are:
/// - from motion::SystemLoad::kCritical on, the system overloaded warning (0xFF01), present
///   while the load stays there (the Clear warning command resets it; it comes back while the
///   load does);
/// - above 1, the regulation misses its periods: the system peak overloaded error (0xFF06),
///   present (a fault reset refused) while the load stays above 1;
/// - above 1 for kWatchdogPeriods control periods without a break, the watchdog resets the
///   device: it starts again as at power-up, with the watchdog error (0xFF02).
/// The manual gives 0xFF03 and 0xFF07 the same causes as 0xFF02 and 0xFF06 and does not tell the
/// pairs apart; the simulation raises the first code of each.
class SystemLoadSupervision {
public:
    static constexpr int kWatchdogPeriods = 100; ///< of the drive's 1 ms control period

    void set_load(double share) { load_.set(share); }
    /// One control period. Returns whether the watchdog resets the device now.
    bool update();
    /// The device started again: the watchdog counts anew.
    void restart() { overloaded_periods_ = 0; }

    bool peak_overloaded() const { return load_.overloaded(); }
    /// The present conditions as error codes (table 110).
    std::vector<DeviceErrorCode> conditions() const;

private:
    motion::SystemLoad load_;
    int overloaded_periods_ = 0;
};

} // namespace eposp::drives::escon2
