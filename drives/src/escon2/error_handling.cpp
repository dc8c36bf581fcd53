#include "eposp/drives/escon2/error_handling.hpp"

#include <algorithm>

namespace eposp::drives::escon2 {
namespace {

constexpr std::uint32_t kWarningFlag = 0x8000'0000; // 6.2.3.2, table 36: bit 31

bool contains(const std::vector<std::uint16_t>& codes, std::uint16_t code) {
    return std::ranges::find(codes, code) != codes.end();
}

} // namespace

ErrorHandling::ErrorHandling(canopen::ObjectDictionary& od)
    : od_(od), history_(od, canopen::GenericErrorBit::FromTheTable) {}

bool ErrorHandling::raise(std::uint16_t code) {
    const DeviceError& error = device_error(code);
    auto& active = error.reaction == FaultReactionCode::Warning ? warnings_ : errors_;
    if (contains(active, code)) {
        return false;
    }
    active.push_back(code);
    const bool warning = error.reaction == FaultReactionCode::Warning;
    history_.record(code | (warning ? kWarningFlag : 0U));
    publish();
    return true;
}

void ErrorHandling::clear_warning(std::uint16_t code) {
    std::erase(warnings_, code);
    publish();
}

void ErrorHandling::fault_reset() {
    std::erase_if(errors_, [](std::uint16_t code) {
        return device_error(code).recovery == ErrorRecovery::FaultReset;
    });
    publish();
}

void ErrorHandling::clear_warnings() {
    std::erase_if(warnings_, [](std::uint16_t code) {
        return device_error(code).recovery == ErrorRecovery::ClearWarning;
    });
    publish();
}

void ErrorHandling::reset() {
    errors_.clear();
    warnings_.clear();
    publish();
}

bool ErrorHandling::needs_device_reset() const {
    return std::ranges::any_of(errors_, [](std::uint16_t code) {
        return device_error(code).recovery == ErrorRecovery::ResetDevice;
    });
}

bool ErrorHandling::active(std::uint16_t code) const {
    return contains(errors_, code) || contains(warnings_, code);
}

// 0x1001: every bit of the active entries; 0x603F: the latest non-erasable error, else the
// latest error, else the latest warning, else 0.
void ErrorHandling::publish() {
    std::uint8_t bits = 0;
    for (const auto* codes : {&errors_, &warnings_}) {
        for (const std::uint16_t code : *codes) {
            bits = static_cast<std::uint8_t>(bits | device_error(code).error_register);
        }
    }
    history_.set_error_register(bits);
    const auto latest = [](const std::vector<std::uint16_t>& codes, auto wanted) {
        const auto found = std::ranges::find_if(codes.rbegin(), codes.rend(), wanted);
        return found == codes.rend() ? std::uint16_t{0} : *found;
    };
    std::uint16_t shown = latest(errors_, [](std::uint16_t code) {
        return device_error(code).recovery == ErrorRecovery::ResetDevice;
    });
    if (shown == 0) {
        shown = latest(errors_, [](std::uint16_t) { return true; });
    }
    if (shown == 0) {
        shown = latest(warnings_, [](std::uint16_t) { return true; });
    }
    od_.set_as(0x603F, 0, shown);
}

} // namespace eposp::drives::escon2
