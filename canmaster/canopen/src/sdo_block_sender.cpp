#include "eposp/canopen/sdo_block_sender.hpp"

#include "eposp/canopen/cob_id.hpp"
#include "eposp/canopen/sdo_protocol.hpp"

#include <algorithm>

namespace eposp::canopen {

SdoBlockSender::SdoBlockSender(core::EventLoop& loop, can::Port& port, core::Duration retry_delay)
    : loop_(loop), port_(port), retry_delay_(retry_delay) {}

void SdoBlockSender::begin(std::uint32_t cob_id, std::span<const std::uint8_t> data) {
    stop();
    cob_id_ = cob_id;
    data_ = data;
    block_offset_ = 0;
    segments_ = 0;
    next_ = 1;
    complete_ = false;
}

void SdoBlockSender::send_block(std::uint8_t block_size) {
    const std::size_t remaining = data_.size() - block_offset_;
    // Even no data takes one segment: the one whose c bit ends the transfer.
    const std::size_t needed =
        std::max<std::size_t>(1, (remaining + sdo::kSegmentSize - 1) / sdo::kSegmentSize);
    segments_ = static_cast<std::uint8_t>(std::min<std::size_t>(block_size, needed));
    block_has_last_ = needed <= block_size;
    next_ = 1;
    pump();
}

void SdoBlockSender::pump() {
    while (next_ <= segments_) {
        const std::size_t offset = block_offset_ + (next_ - 1U) * sdo::kSegmentSize;
        const auto chunk =
            data_.subspan(offset, std::min(sdo::kSegmentSize, data_.size() - offset));
        const bool last = block_has_last_ && next_ == segments_;
        const auto frame = make_frame(
            cob_id_, sdo::segment_message(sdo::block_segment_command(next_, last), chunk));
        if (port_.send(frame) == can::SendStatus::TxOverflow) {
            retry_ = core::ScopedTimer(loop_, loop_.after(retry_delay_, [this] { pump(); }));
            return;
        }
        // Any other refusal (bus-off, disconnected) loses the frame as the bus would: the
        // receiver acknowledges less, or the transfer times out.
        ++next_;
    }
}

bool SdoBlockSender::acknowledge(std::uint8_t ackseq) {
    if (ackseq >= next_) {
        return false;
    }
    retry_.cancel();
    block_offset_ = std::min(data_.size(), block_offset_ + ackseq * sdo::kSegmentSize);
    complete_ = block_has_last_ && ackseq == segments_;
    return true;
}

std::size_t SdoBlockSender::unused_in_last_segment() const {
    const std::size_t used = data_.size() % sdo::kSegmentSize;
    return data_.empty() ? sdo::kSegmentSize : (used == 0 ? 0 : sdo::kSegmentSize - used);
}

void SdoBlockSender::stop() {
    retry_.cancel();
}

} // namespace eposp::canopen
