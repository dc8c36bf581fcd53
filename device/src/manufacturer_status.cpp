#include "manufacturer_status.hpp"

#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/error_entry.hpp"

namespace eposp::device {
namespace {

constexpr std::uint16_t kManufacturerStatusIndex = 0x1002;
constexpr std::uint32_t kMasterGenericWarning = 1U << 16;
constexpr std::uint32_t kMasterCommunicationWarning = 1U << 20;
constexpr std::uint32_t kMasterManufacturerWarning = 1U << 23;

std::uint32_t warning_bits(std::uint16_t code) {
    std::uint32_t bits = kMasterGenericWarning;
    // Table 1: the boot-up errors 0x638x and the CAN errors 0x8xxx concern the communication.
    if ((code & 0xFF00) == 0x6300 || (code & 0xF000) == 0x8000) {
        bits |= kMasterCommunicationWarning;
    }
    if ((code & 0xFF00) == 0xFF00) {
        bits |= kMasterManufacturerWarning;
    }
    return bits;
}

} // namespace

ManufacturerStatus::ManufacturerStatus(canopen::ObjectDictionary& od) : od_(od) {
    od.find(kManufacturerStatusIndex, 0)->on_read = [this] {
        return canopen::encode(value());
    };
}

void ManufacturerStatus::on_emergency(std::uint8_t port, const canopen::Emergency& emergency) {
    slave_registers_[{port, emergency.node}] = emergency.error_register;
}

std::uint32_t ManufacturerStatus::value() const {
    std::uint32_t status = 0;
    for (const auto& [slave, error_register] : slave_registers_) {
        status |= error_register;
    }
    status |= std::uint32_t{od_.get_as<std::uint8_t>(0x1001, 0)} << 8;
    const auto entries = od_.get_as<std::uint8_t>(0x1003, 0);
    for (std::uint8_t sub = 1; sub <= entries; ++sub) {
        const ErrorEntry entry = ErrorEntry::decode(od_.get_as<std::uint32_t>(0x1003, sub));
        if (entry.warning) {
            status |= warning_bits(entry.code);
        }
    }
    return status;
}

} // namespace eposp::device
