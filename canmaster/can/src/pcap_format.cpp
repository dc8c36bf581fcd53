#include "pcap_format.hpp"

#include "socketcan_id.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace eposp::can::pcap {
namespace {

constexpr std::size_t kLengthOffset = 4;

std::uint32_t socketcan_id(const Frame& frame) {
    if (frame.error) {
        return socketcan::kErrorFlag | (frame.id & socketcan::kIdMask);
    }
    return frame.id | (frame.extended ? socketcan::kExtendedFlag : 0) |
           (frame.remote ? socketcan::kRemoteFlag : 0);
}

} // namespace

CanFrameBytes encode_can_frame(const Frame& frame) {
    CanFrameBytes bytes{};
    const std::uint32_t id = socketcan_id(frame);
    // LINKTYPE_CAN_SOCKETCAN stores can_id in network byte order, whatever the host's.
    bytes[0] = static_cast<std::uint8_t>(id >> 24);
    bytes[1] = static_cast<std::uint8_t>(id >> 16);
    bytes[2] = static_cast<std::uint8_t>(id >> 8);
    bytes[3] = static_cast<std::uint8_t>(id);
    bytes[kLengthOffset] = frame.dlc; // a remote frame's requested length, as SocketCAN has it
    const auto payload = frame.payload();
    std::copy(payload.begin(), payload.end(), bytes.begin() + kCanHeaderSize);
    return bytes;
}

core::Result<Frame> decode_can_frame(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < kCanHeaderSize) {
        return core::Error{
            fmt::format("{} bytes are too short for a SocketCAN frame header", bytes.size())};
    }
    const std::uint32_t id = (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
                             (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]};
    const std::uint8_t length = bytes[kLengthOffset];
    if (length > kMaxDataLength) {
        return core::Error{
            fmt::format("payload length {} is above 8 (CAN FD is not supported)", length)};
    }
    Frame frame;
    frame.error = (id & socketcan::kErrorFlag) != 0;
    frame.extended = !frame.error && (id & socketcan::kExtendedFlag) != 0;
    frame.remote = !frame.error && (id & socketcan::kRemoteFlag) != 0;
    frame.id = id & socketcan::kIdMask;
    frame.dlc = length;
    if (!frame.extended && !frame.error && frame.id > kMaxStandardId) {
        return core::Error{fmt::format("standard identifier 0x{:X} is above 0x7FF", frame.id)};
    }
    if (frame.remote) {
        return frame;
    }
    if (bytes.size() < kCanHeaderSize + length) {
        return core::Error{fmt::format("payload of {} bytes is cut short", length)};
    }
    std::copy_n(bytes.begin() + kCanHeaderSize, length, frame.data.begin());
    return frame;
}

} // namespace eposp::can::pcap
