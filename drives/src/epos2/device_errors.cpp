#include "eposp/drives/epos2/device_errors.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <stdexcept>

namespace eposp::drives::epos2 {
namespace {

using enum motion::FaultClass;

// EPOS2 FW spec 4.2.1, table 4-11, row by row: code, error register, fault reaction code,
// position reset, name.
constexpr std::array kDeviceErrors = std::to_array<DeviceError>({
    {0x1000, 0b00000001, Critical, false, "Generic Error"},
    {0x2310, 0b00000010, Critical, false, "Overcurrent Error"},
    {0x2320, 0b00000010, Critical, false, "Short Circuit/Earth Leakage Error"},
    {0x3210, 0b00000100, Critical, false, "Overvoltage Error"},
    {0x3220, 0b00000100, Critical, false, "Undervoltage Error"},
    {0x4210, 0b00001000, Critical, false, "Overtemperature Error"},
    {0x5113, 0b00000100, Critical, false, "Logic Supply Voltage Too Low Error"},
    {0x5114, 0b00000100, Critical, false, "Supply Voltage Output Stage Too Low Error"},
    {0x6100, 0b00100000, Critical, false, "Internal Software Error"},
    {0x6320, 0b00100000, Device, false, "Software Parameter Error"},
    {0x7320, 0b00100000, Critical, true, "Position Sensor Error"},
    {0x8110, 0b00010000, Communication, false, "CAN Overrun Error (Objects lost)"},
    {0x8111, 0b00010000, Communication, false, "CAN Overrun Error"},
    {0x8120, 0b00010000, Communication, false, "CAN Passive Mode Error"},
    {0x8130, 0b00010000, Communication, false, "CAN Life Guarding Error or Heartbeat Error"},
    {0x8150, 0b00010000, Communication, false, "CAN Transmit COB-ID Collision Error"},
    {0x81FD, 0b00010000, Communication, false, "CAN Bus Off Error"},
    {0x81FE, 0b00010000, Communication, false, "CAN Rx Queue Overflow Error"},
    {0x81FF, 0b00010000, Communication, false, "CAN Tx Queue Overflow Error"},
    {0x8210, 0b00010000, Communication, false, "CAN PDO Length Error"},
    {0x8611, 0b00100000, Device, false, "Following Error"},
    {0xFF01, 0b10000000, Critical, true, "Hall Sensor Error"},
    {0xFF02, 0b10000000, Critical, true, "Index Processing Error"},
    {0xFF03, 0b10000000, Critical, true, "Encoder Resolution Error"},
    {0xFF04, 0b10000000, Critical, true, "Hall Sensor not found Error"},
    {0xFF06, 0b10000000, Device, false, "Negative Limit Switch Error"},
    {0xFF07, 0b10000000, Device, false, "Positive Limit Switch Error"},
    {0xFF08, 0b10000000, Device, true, "Hall Angle Detection Error"},
    {0xFF09, 0b10000000, Device, false, "Software Position Limit Error"},
    {0xFF0A, 0b10000000, Critical, true, "Position Sensor Breach Error"},
    {0xFF0B, 0b00100000, Critical, false, "System Overloaded Error"},
    {0xFF0C, 0b00100000, Device, false, "Interpolated Position Mode Error"},
    {0xFF0D, 0b00100000, Critical, false, "Auto Tuning Identification Error"},
    {0xFF0F, 0b00100000, Critical, false, "Gear Scaling Factor Error"},
    {0xFF10, 0b00100000, Device, false, "Controller Gain Error"},
    {0xFF11, 0b00100000, Critical, false, "Main Sensor Direction Error"},
    {0xFF12, 0b00100000, Critical, false, "Auxiliary Sensor Direction Error"},
});

} // namespace

std::span<const DeviceError> device_errors() {
    return kDeviceErrors;
}

const DeviceError& device_error(std::uint16_t code) {
    const auto* row = std::find_if(kDeviceErrors.begin(), kDeviceErrors.end(),
                                   [code](const DeviceError& error) { return error.code == code; });
    if (row == kDeviceErrors.end()) {
        throw std::invalid_argument(fmt::format("0x{:04X} is not an error of table 4-11", code));
    }
    return *row;
}

} // namespace eposp::drives::epos2
