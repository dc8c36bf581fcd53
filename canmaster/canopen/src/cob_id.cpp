#include "eposp/canopen/cob_id.hpp"

namespace eposp::canopen {
namespace {

// CiA 301 7.3.5 (restricted CAN-IDs): identifiers no configurable communication object may use.
bool restricted(std::uint32_t id) {
    return id == 0x000 || (id >= 0x001 && id <= 0x07F) || (id >= 0x101 && id <= 0x180) ||
           (id >= 0x581 && id <= 0x5FF) || (id >= 0x601 && id <= 0x67F) ||
           (id >= 0x6E0 && id <= 0x6FF) || (id >= 0x701 && id <= 0x77F) ||
           (id >= 0x780 && id <= 0x7FF);
}

} // namespace

bool cob_id_acceptable(std::uint32_t cob_id) {
    if ((cob_id & kCobIdExtended) != 0) {
        return true;
    }
    const bool unused_bits_clear = (cob_id & can::kMaxExtendedId & ~can::kMaxStandardId) == 0;
    return unused_bits_clear && !restricted(can_id(cob_id));
}

can::Frame make_frame(std::uint32_t cob_id, std::span<const std::uint8_t> data) {
    return can::Frame::data_frame(can_id(cob_id), data, (cob_id & kCobIdExtended) != 0);
}

} // namespace eposp::canopen
