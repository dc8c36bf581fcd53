#pragma once

#include "eposp/canopen/emcy_consumer.hpp"
#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <map>
#include <utility>

namespace eposp::device {

/// 0x1002 Manufacturer Status Register (EPOS P 10.3, table 3): bits 0..7 the error registers
/// the slaves of both ports last reported by EMCY, OR-ed; bits 8..15 a copy of 0x1001; bit 16
/// a warning of the master in the error history, bit 20 a communication warning (a CAN or
/// boot-up code, 0x63xx / 0x8xxx), bit 23 a manufacturer-specific one (0xFFxx). Warnings last
/// until the history is cleared. The register is computed when read.
class ManufacturerStatus {
public:
    /// Binds 0x1002 of `od`, which must outlive this and not move.
    explicit ManufacturerStatus(canopen::ObjectDictionary& od);
    ManufacturerStatus(const ManufacturerStatus&) = delete;
    ManufacturerStatus& operator=(const ManufacturerStatus&) = delete;

    /// An EMCY a slave of `port` sent: its error register from now on.
    void on_emergency(std::uint8_t port, const canopen::Emergency& emergency);
    std::uint32_t value() const;

private:
    const canopen::ObjectDictionary& od_;
    std::map<std::pair<std::uint8_t, canopen::NodeId>, std::uint8_t> slave_registers_;
};

} // namespace eposp::device
