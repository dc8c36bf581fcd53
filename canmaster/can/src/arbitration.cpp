#include "eposp/can/arbitration.hpp"

namespace eposp::can {
namespace {

// Layout, most significant bit first: base id (11) | RTR or SRR | IDE | id extension (18) | RTR.
constexpr unsigned kBaseIdShift = 21;
constexpr unsigned kTwelfthBitShift = 20;
constexpr unsigned kIdeShift = 19;
constexpr unsigned kExtensionShift = 1;
constexpr std::uint32_t kExtensionMask = 0x3FFFF;

std::uint32_t bit(bool value, unsigned shift) {
    return static_cast<std::uint32_t>(value) << shift;
}

} // namespace

std::uint32_t arbitration_field(const Frame& frame) {
    if (!frame.extended) {
        // Standard frames end their arbitration at RTR; IDE (dominant) still decides against
        // an extended frame with the same base identifier.
        return frame.id << kBaseIdShift | bit(frame.remote, kTwelfthBitShift);
    }
    const std::uint32_t srr = bit(true, kTwelfthBitShift);
    const std::uint32_t ide = bit(true, kIdeShift);
    return (frame.id >> 18) << kBaseIdShift | srr | ide |
           (frame.id & kExtensionMask) << kExtensionShift | bit(frame.remote, 0);
}

} // namespace eposp::can
