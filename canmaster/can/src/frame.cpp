#include "eposp/can/frame.hpp"

#include <algorithm>
#include <cassert>

namespace eposp::can {

Frame Frame::data_frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes,
                        bool extended) {
    return data_frame(id, std::span<const std::uint8_t>(bytes.begin(), bytes.size()), extended);
}

Frame Frame::data_frame(std::uint32_t id, std::span<const std::uint8_t> bytes, bool extended) {
    assert(bytes.size() <= kMaxDataLength);
    Frame frame;
    frame.id = id;
    frame.extended = extended;
    frame.dlc = static_cast<std::uint8_t>(std::min<std::size_t>(bytes.size(), kMaxDataLength));
    std::copy_n(bytes.begin(), frame.dlc, frame.data.begin());
    return frame;
}

Frame Frame::remote_frame(std::uint32_t id, std::uint8_t dlc, bool extended) {
    Frame frame;
    frame.id = id;
    frame.extended = extended;
    frame.remote = true;
    frame.dlc = dlc;
    return frame;
}

bool Frame::valid() const {
    return !error && dlc <= kMaxDataLength && id <= (extended ? kMaxExtendedId : kMaxStandardId);
}

bool operator==(const Frame& a, const Frame& b) {
    return a.id == b.id && a.extended == b.extended && a.remote == b.remote && a.error == b.error &&
           a.dlc == b.dlc && std::ranges::equal(a.payload(), b.payload());
}

} // namespace eposp::can
