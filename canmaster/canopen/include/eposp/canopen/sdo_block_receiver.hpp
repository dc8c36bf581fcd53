#pragma once

#include "eposp/canopen/sdo_protocol.hpp"
#include "eposp/canopen/value_codec.hpp"

#include <cstdint>
#include <span>

namespace eposp::canopen {

/// The receiving side of a block transfer (CiA 301 7.2.4.3.9, 7.2.4.3.12): takes the segments of
/// a sub-block in sequence; after a lost segment it ignores the rest of the sub-block, whose end
/// it still recognises, so that its acknowledgement makes the sender repeat from the gap.
class SdoBlockReceiver {
public:
    enum class Outcome {
        Continue,        ///< more segments of this sub-block are due
        BlockEnd,        ///< the sub-block ended: acknowledge ackseq()
        InvalidSequence, ///< seqno 0 or above blksize: abort 0x05040003
    };

    /// Starts receiving; the segments' bytes are appended to `data` (all 7 of the last one too:
    /// the end message says how many of them to drop).
    void begin(Bytes& data);
    void start_block(std::uint8_t block_size);
    Outcome on_segment(std::span<const std::uint8_t, sdo::kMessageSize> bytes);

    std::uint8_t ackseq() const { return ackseq_; }
    std::uint8_t block_size() const { return block_size_; }
    /// The segment with c set was taken: the end message is next.
    bool last_received() const { return last_received_; }

private:
    Bytes* data_ = nullptr;
    std::uint8_t block_size_ = 0;
    std::uint8_t ackseq_ = 0;
    bool last_received_ = false;
};

} // namespace eposp::canopen
