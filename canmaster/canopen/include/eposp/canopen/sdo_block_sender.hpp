#pragma once

#include "eposp/can/port.hpp"
#include "eposp/core/event_loop.hpp"

#include <cstddef>
#include <cstdint>
#include <span>

namespace eposp::canopen {

/// The sending side of a block transfer (CiA 301 7.2.4.3.9 block download, 7.2.4.3.12 block
/// upload): sub-blocks of segments numbered 1..blksize, 7 bytes each, c set on the segment that
/// carries the last byte; after each sub-block the receiver acknowledges the last segment it
/// took in sequence, and the next sub-block resumes after it. A controller has no "frame sent"
/// event, so when the transmit queue is full the rest of the sub-block follows after a delay.
class SdoBlockSender {
public:
    SdoBlockSender(core::EventLoop& loop, can::Port& port, core::Duration retry_delay);

    /// Starts sending `data`, which must stay alive and unchanged until the transfer ends.
    void begin(std::uint32_t cob_id, std::span<const std::uint8_t> data);
    /// Sends the next sub-block: up to `block_size` segments from the first unacknowledged byte.
    void send_block(std::uint8_t block_size);
    /// Takes the receiver's ackseq; false when it names a segment that was not sent (CiA 301:
    /// abort 0x05040003).
    bool acknowledge(std::uint8_t ackseq);
    /// Every segment, the last one included, has been acknowledged.
    bool complete() const { return complete_; }
    /// n of the end message: the bytes of the last segment that carry no data.
    std::size_t unused_in_last_segment() const;
    /// Stops sending (the transfer ended or was aborted).
    void stop();

private:
    void pump();

    core::EventLoop& loop_;
    can::Port& port_;
    core::Duration retry_delay_;
    core::ScopedTimer retry_;
    std::uint32_t cob_id_ = 0;
    std::span<const std::uint8_t> data_;
    std::size_t block_offset_ = 0; ///< first byte of the current sub-block
    std::uint8_t segments_ = 0;    ///< segments in the current sub-block
    std::uint8_t next_ = 1;        ///< sequence number of the next segment to send
    bool block_has_last_ = false;
    bool complete_ = false;
};

} // namespace eposp::canopen
