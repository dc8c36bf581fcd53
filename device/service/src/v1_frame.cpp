#include "eposp/service/v1_frame.hpp"

#include "eposp/service/crc.hpp"

namespace eposp::service {

bool is_v1_request_opcode(std::uint8_t byte) {
    return byte != kAnswerOpCode && byte != kReady && byte != kNotReady;
}

std::vector<std::uint8_t> v1_frame_rest(const Frame& frame) {
    const std::uint16_t crc = v1_crc(frame); // checks the size
    std::vector<std::uint8_t> bytes;
    bytes.reserve(frame.data.size() + 3);
    bytes.push_back(static_cast<std::uint8_t>(frame.words() - 1));
    bytes.insert(bytes.end(), frame.data.begin(), frame.data.end());
    bytes.push_back(static_cast<std::uint8_t>(crc));
    bytes.push_back(static_cast<std::uint8_t>(crc >> 8));
    return bytes;
}

V1FrameReader::Status V1FrameReader::push(std::uint8_t byte) {
    if (!have_length_) {
        have_length_ = true;
        expected_data_ = (std::size_t{byte} + 1) * 2;
        frame_.data.reserve(expected_data_);
        return Status::Incomplete;
    }
    if (frame_.data.size() < expected_data_) {
        frame_.data.push_back(byte);
        return Status::Incomplete;
    }
    crc_ = static_cast<std::uint16_t>(crc_ | byte << (8 * crc_bytes_));
    if (++crc_bytes_ < 2) {
        return Status::Incomplete;
    }
    return crc_ == v1_crc(frame_) ? Status::Complete : Status::BadCrc;
}

} // namespace eposp::service
