#include "eposp/service/v2_encoder.hpp"

#include "eposp/service/crc.hpp"

namespace eposp::service {

std::vector<std::uint8_t> encode_v2(const Frame& frame) {
    const std::uint16_t crc = v2_crc(frame); // checks the size
    std::vector<std::uint8_t> bytes{kV2Dle, kV2Stx};
    bytes.reserve(2 * (frame.data.size() + 4) + 2);
    const auto stuffed = [&bytes](std::uint8_t byte) {
        bytes.push_back(byte);
        if (byte == kV2Dle) {
            bytes.push_back(kV2Dle);
        }
    };
    stuffed(frame.opcode);
    stuffed(static_cast<std::uint8_t>(frame.words()));
    for (const std::uint8_t byte : frame.data) {
        stuffed(byte);
    }
    stuffed(static_cast<std::uint8_t>(crc));
    stuffed(static_cast<std::uint8_t>(crc >> 8));
    return bytes;
}

} // namespace eposp::service
