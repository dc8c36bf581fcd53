#include "interpolation_buffer.hpp"

namespace eposp::drives::epos2 {

PvtRecord decode_pvt_record(std::uint64_t raw) {
    // The velocity is the signed 24-bit field of bits 32..55.
    const auto velocity_field = static_cast<std::uint32_t>((raw >> 32) & 0xFFFFFF);
    const std::int32_t velocity = (velocity_field & 0x800000) != 0
                                      ? static_cast<std::int32_t>(velocity_field) - 0x1000000
                                      : static_cast<std::int32_t>(velocity_field);
    return {.position = static_cast<std::int32_t>(static_cast<std::uint32_t>(raw & 0xFFFFFFFF)),
            .velocity = velocity,
            .time_ms = static_cast<std::uint8_t>(raw >> 56)};
}

void InterpolationBuffer::clear() {
    records_.clear();
    enabled_ = false;
    flags_ = 0;
}

bool InterpolationBuffer::push(const PvtRecord& record) {
    if (!enabled_) {
        return true;
    }
    if (records_.size() == kCapacity) {
        flags_ |= ipm_status::kOverflowError;
        return false;
    }
    records_.push_back(record);
    return true;
}

std::optional<PvtRecord> InterpolationBuffer::pop() {
    if (records_.empty()) {
        return std::nullopt;
    }
    const PvtRecord record = records_.front();
    records_.pop_front();
    return record;
}

std::uint16_t InterpolationBuffer::status(std::uint16_t underflow_level,
                                          std::uint16_t overflow_level, bool ip_mode_active) const {
    std::uint16_t status = flags_;
    if (records_.size() < underflow_level) {
        status |= ipm_status::kUnderflowWarning;
    }
    if (records_.size() > overflow_level) {
        status |= ipm_status::kOverflowWarning;
    }
    if (enabled_) {
        status |= ipm_status::kBufferEnabled;
    }
    if (ip_mode_active) {
        status |= ipm_status::kIpModeActive;
    }
    return status;
}

} // namespace eposp::drives::epos2
