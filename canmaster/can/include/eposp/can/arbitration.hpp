#pragma once

#include "eposp/can/frame.hpp"

#include <cstdint>

namespace eposp::can {

/// The arbitration field of `frame` read as a number, so that the frame with the lower value
/// wins bus arbitration (ISO 11898-1:2015, 10.4.2.3 and 10.8): the bits in wire order, base
/// identifier first, then RTR (standard) or SRR (extended), IDE, and for extended frames the
/// identifier extension and RTR. A dominant bit (0) wins over a recessive one, so a standard
/// data frame beats an extended frame with the same base identifier through RTR/SRR, a standard
/// remote frame beats it through IDE, and a data frame beats a remote frame with its identifier.
/// Inline: arbitration compares the heads of the queues for every frame on the bus.
inline std::uint32_t arbitration_field(const Frame& frame) {
    // Layout, most significant bit first: base id (11) | RTR or SRR | IDE | id extension (18) |
    // RTR.
    constexpr unsigned kBaseIdShift = 21;
    constexpr unsigned kTwelfthBitShift = 20;
    constexpr unsigned kIdeShift = 19;
    constexpr unsigned kExtensionShift = 1;
    constexpr std::uint32_t kExtensionMask = 0x3FFFF;
    const std::uint32_t remote = frame.remote ? 1U : 0U;
    if (!frame.extended) {
        // Standard frames end their arbitration at RTR; IDE (dominant) still decides against
        // an extended frame with the same base identifier.
        return frame.id << kBaseIdShift | remote << kTwelfthBitShift;
    }
    const std::uint32_t srr = 1U << kTwelfthBitShift;
    const std::uint32_t ide = 1U << kIdeShift;
    return (frame.id >> 18) << kBaseIdShift | srr | ide |
           (frame.id & kExtensionMask) << kExtensionShift | remote;
}

/// True when `a` wins arbitration against `b`.
inline bool wins_arbitration(const Frame& a, const Frame& b) {
    return arbitration_field(a) < arbitration_field(b);
}

} // namespace eposp::can
