#include "eposp/drives/escon2/protection/system_load_supervision.hpp"

namespace eposp::drives::escon2 {

bool SystemLoadSupervision::update() {
    overloaded_periods_ = peak_overloaded() ? overloaded_periods_ + 1 : 0;
    return overloaded_periods_ >= kWatchdogPeriods;
}

std::vector<DeviceErrorCode> SystemLoadSupervision::conditions() const {
    std::vector<DeviceErrorCode> codes;
    if (load_.critical()) {
        codes.push_back(DeviceErrorCode::SystemOverloadedWarning);
    }
    if (peak_overloaded()) {
        codes.push_back(DeviceErrorCode::SystemPeakOverloaded);
    }
    return codes;
}

} // namespace eposp::drives::escon2
