#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>

namespace eposp::can {

inline constexpr std::uint32_t kMaxStandardId = 0x7FF;
inline constexpr std::uint32_t kMaxExtendedId = 0x1FFF'FFFF;
inline constexpr std::uint8_t kMaxDataLength = 8;

/// A classic CAN frame as ISO 11898-1 defines it: 11- or 29-bit identifier, data or remote
/// (RTR), DLC 0..8. An error frame (`error` set) is what a bus signals on a detected error;
/// like SocketCAN's, its `id` holds the error class bits and `data` the details, so traces
/// record it the way candump and Wireshark show error frames. Nodes never send error frames.
struct Frame {
    std::uint32_t id = 0;
    bool extended = false;
    bool remote = false;
    bool error = false;
    std::uint8_t dlc = 0;
    std::array<std::uint8_t, kMaxDataLength> data{};

    static Frame data_frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes,
                            bool extended = false);
    static Frame data_frame(std::uint32_t id, std::span<const std::uint8_t> bytes,
                            bool extended = false);
    static Frame remote_frame(std::uint32_t id, std::uint8_t dlc, bool extended = false);

    /// The bytes carried on the wire: `dlc` bytes of a data frame, none for a remote frame.
    /// Inline: the bus reads it for every frame.
    std::span<const std::uint8_t> payload() const {
        if (remote) {
            return {};
        }
        return {data.data(), dlc < kMaxDataLength ? dlc : kMaxDataLength};
    }

    /// A frame a node may send: identifier within its format, DLC 0..8, not an error frame.
    bool valid() const;

    /// Frames are equal when everything on the wire is equal; bytes beyond the DLC are ignored.
    friend bool operator==(const Frame& a, const Frame& b);
};

} // namespace eposp::can
