#include "eposp/canopen/sdo_protocol.hpp"

#include "eposp/canopen/cob_id.hpp"

#include <algorithm>
#include <boost/crc.hpp>

namespace eposp::canopen::sdo {

Message message(std::uint8_t command, Multiplexer mux, std::uint32_t value) {
    return {command,
            static_cast<std::uint8_t>(mux.index),
            static_cast<std::uint8_t>(mux.index >> 8),
            mux.sub_index,
            static_cast<std::uint8_t>(value),
            static_cast<std::uint8_t>(value >> 8),
            static_cast<std::uint8_t>(value >> 16),
            static_cast<std::uint8_t>(value >> 24)};
}

Message segment_message(std::uint8_t command, std::span<const std::uint8_t> data) {
    Message out{command};
    std::copy_n(data.begin(), std::min(data.size(), kSegmentSize), out.begin() + 1);
    return out;
}

Message abort_message(Multiplexer mux, AbortCode code) {
    return message(kAbortCommand, mux, static_cast<std::uint32_t>(code));
}

Multiplexer multiplexer_of(std::span<const std::uint8_t, kMessageSize> bytes) {
    return {static_cast<std::uint16_t>(bytes[1] | bytes[2] << 8), bytes[3]};
}

std::uint32_t value_of(std::span<const std::uint8_t, kMessageSize> bytes) {
    return static_cast<std::uint32_t>(bytes[4]) | static_cast<std::uint32_t>(bytes[5]) << 8 |
           static_cast<std::uint32_t>(bytes[6]) << 16 | static_cast<std::uint32_t>(bytes[7]) << 24;
}

bool is_message_on(const can::Frame& frame, std::uint32_t cob_id) {
    return frame.dlc == kMessageSize && matches(cob_id, frame);
}

std::span<const std::uint8_t, kMessageSize> bytes_of(const can::Frame& frame) {
    return std::span<const std::uint8_t, kMessageSize>(frame.data);
}

std::uint16_t block_crc(std::span<const std::uint8_t> data) {
    boost::crc_optimal<16, 0x1021, 0x0000, 0x0000, false, false> crc;
    crc.process_bytes(data.data(), data.size());
    return crc.checksum();
}

} // namespace eposp::canopen::sdo
