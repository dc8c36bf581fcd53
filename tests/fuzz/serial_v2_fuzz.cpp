// What may arrive on the USB link (v2), as arbitrary bytes in arbitrary pieces, with the frame
// timeout striking between pieces: the decoder (v2_decoder.hpp) never crashes, finds the same
// frames however the bytes are cut, every frame it delivers has a right CRC and re-encodes to
// bytes that decode to the same frame, and after a timeout no frame is in progress.
//
// Input: [control] [bytes...]; control bits 0..3: piece size - 1; bit 4: a timeout after every
// piece (then the frames may differ from those of the whole stream, and are not compared).

#include "eposp/service/crc.hpp"
#include "eposp/service/frame_limits.hpp"
#include "eposp/service/v2_decoder.hpp"
#include "eposp/service/v2_encoder.hpp"
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace {

namespace service = eposp::service;
using eposp::fuzz::require;

void check_frame(const service::Frame& frame) {
    require(frame.data.size() % 2 == 0 && frame.words() <= service::kV2MaxWords,
            "a frame is whole words, at most 255");
    std::vector<service::Frame> again;
    service::V2Decoder decoder([&again](const service::Frame& f) { again.push_back(f); });
    decoder.receive(service::encode_v2(frame));
    require(again.size() == 1 && again.front() == frame && !decoder.mid_frame(),
            "a delivered frame re-encodes to bytes that decode to it");
}

std::vector<service::Frame> decode(std::span<const std::uint8_t> stream, std::size_t piece,
                                   bool timeouts) {
    std::vector<service::Frame> frames;
    service::V2Decoder decoder([&frames](const service::Frame& frame) {
        check_frame(frame);
        frames.push_back(frame);
    });
    for (std::size_t at = 0; at < stream.size(); at += piece) {
        decoder.receive(stream.subspan(at, std::min(piece, stream.size() - at)));
        if (timeouts) {
            decoder.on_timeout();
            require(!decoder.mid_frame(), "no frame is in progress after a timeout");
        }
    }
    const auto& counters = decoder.counters();
    require(counters.frames == frames.size(), "every frame found is counted");
    return frames;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    const std::size_t piece = (data[0] & 0x0Fu) + 1u;
    const bool timeouts = (data[0] & 0x10u) != 0;
    const std::span<const std::uint8_t> stream(data + 1, size - 1);
    const std::vector<service::Frame> frames = decode(stream, piece, timeouts);
    if (!timeouts) {
        require(frames == decode(stream, std::max<std::size_t>(stream.size(), 1), false),
                "the frames found do not depend on how the bytes are cut");
    }
    return 0;
}
