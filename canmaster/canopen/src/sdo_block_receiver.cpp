#include "eposp/canopen/sdo_block_receiver.hpp"

namespace eposp::canopen {

void SdoBlockReceiver::begin(Bytes& data) {
    data_ = &data;
    last_received_ = false;
}

void SdoBlockReceiver::start_block(std::uint8_t block_size) {
    block_size_ = block_size;
    ackseq_ = 0;
}

SdoBlockReceiver::Outcome
SdoBlockReceiver::on_segment(std::span<const std::uint8_t, sdo::kMessageSize> bytes) {
    const auto sequence = static_cast<std::uint8_t>(bytes[0] & 0x7F);
    const bool last = (bytes[0] & 0x80) != 0;
    if (sequence == 0 || sequence > block_size_) {
        return Outcome::InvalidSequence;
    }
    if (!last_received_ && sequence == ackseq_ + 1) {
        data_->insert(data_->end(), bytes.begin() + 1, bytes.end());
        ackseq_ = sequence;
        last_received_ = last;
    }
    return sequence == block_size_ || last ? Outcome::BlockEnd : Outcome::Continue;
}

} // namespace eposp::canopen
