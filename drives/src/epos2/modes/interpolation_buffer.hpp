#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

namespace eposp::drives::epos2 {

/// A PVT reference point as Interpolation Data Record 0x20C1 carries it (EPOS2 FW spec 5.5.4.1,
/// table 5-27: time u8 | velocity s24 | position s32, MSB to LSB): the end point of a segment
/// and the segment's duration. Time 0 ends the motion (8.2.69).
struct PvtRecord {
    std::int32_t position = 0; ///< qc, absolute
    std::int32_t velocity = 0; ///< rpm
    std::uint8_t time_ms = 0;
};

PvtRecord decode_pvt_record(std::uint64_t raw);

/// Table 8-100: the bits of Interpolation Buffer Status 0x20C4 sub 1.
namespace ipm_status {
inline constexpr std::uint16_t kUnderflowWarning = 1U << 0;
inline constexpr std::uint16_t kOverflowWarning = 1U << 1;
inline constexpr std::uint16_t kVelocityWarning = 1U << 2;
inline constexpr std::uint16_t kAccelerationWarning = 1U << 3;
inline constexpr std::uint16_t kUnderflowError = 1U << 8;
inline constexpr std::uint16_t kOverflowError = 1U << 9;
inline constexpr std::uint16_t kVelocityError = 1U << 10;
inline constexpr std::uint16_t kAccelerationError = 1U << 11;
inline constexpr std::uint16_t kBufferEnabled = 1U << 14;
inline constexpr std::uint16_t kIpModeActive = 1U << 15;
} // namespace ipm_status

/// The IPM input FIFO (5.5.4, 8.2.123): 64 records; written only while access is enabled (0x60C4
/// sub 6 = 1). The velocity, acceleration and error flags stay set until the buffer is cleared.
class InterpolationBuffer {
public:
    static constexpr std::size_t kCapacity = 64;

    /// 0x60C4 sub 6 = 1.
    void enable() { enabled_ = true; }
    /// 0x60C4 sub 6 = 0: every record and flag dropped, access denied.
    void clear();
    bool enabled() const { return enabled_; }

    /// A record written to 0x20C1: ignored while access is denied; when full, the record is lost
    /// and the overflow error set (false).
    bool push(const PvtRecord& record);
    std::optional<PvtRecord> pop();
    std::size_t size() const { return records_.size(); }

    /// Latches one of the flags of table 8-100 (the velocity, acceleration and error bits).
    void flag(std::uint16_t bits) { flags_ |= bits; }
    /// 0x20C4 sub 1 with the warning levels of sub 2 and 3.
    std::uint16_t status(std::uint16_t underflow_level, std::uint16_t overflow_level,
                         bool ip_mode_active) const;

private:
    std::deque<PvtRecord> records_;
    bool enabled_ = false;
    std::uint16_t flags_ = 0;
};

} // namespace eposp::drives::epos2
