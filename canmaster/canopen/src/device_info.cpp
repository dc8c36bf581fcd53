#include "eposp/canopen/device_info.hpp"

namespace eposp::canopen {

std::set<std::uint32_t> DeviceInfo::bit_rates() const {
    std::set<std::uint32_t> rates;
    for (const std::uint16_t kbit : baud_rates_kbit) {
        rates.insert(std::uint32_t{kbit} * 1000);
    }
    return rates;
}

} // namespace eposp::canopen
