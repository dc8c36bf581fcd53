#pragma once

#include "eposp/service/frame.hpp"

#include <cstdint>
#include <functional>
#include <span>

namespace eposp::service {

/// Why the USB decoder dropped what it had of a frame.
enum class V2Error {
    CrcError,      ///< the frame was whole and its CRC wrong
    StuffingError, ///< 0x90 followed by neither 0x90 nor 0x02
    Interrupted,   ///< 0x90 0x02 started a new frame before this one was whole
    Timeout,       ///< on_timeout() mid-frame
};

/// Finds the frames of the USB link (v2) in a byte stream, for either side (v2 has no
/// handshakes): maxon EPOS2 communication guide, "USB protocol". Bytes outside a frame are
/// skipped up to the next 0x90 0x02; inside one, 0x90 0x90 is a data byte 0x90, 0x90 0x02 starts
/// a new frame (the unfinished one is dropped: so a Len larger than what follows is dropped)
/// and 0x90 followed by anything else drops the frame. A whole frame with a right CRC goes to
/// the frame callback, each dropped one to the error callback and the counters.
///
/// At most one frame (255 words) is buffered. Time is the owner's: while mid_frame() it arms
/// the frame timeout (object 0x5005, restarted at each byte) and calls on_timeout().
class V2Decoder {
public:
    using OnFrame = std::function<void(const Frame&)>;
    using OnError = std::function<void(V2Error)>;

    struct Counters {
        std::uint64_t frames = 0;
        std::uint64_t crc_errors = 0;
        std::uint64_t stuffing_errors = 0;
        std::uint64_t interrupted = 0;
        std::uint64_t timeouts = 0;
        std::uint64_t skipped_bytes = 0; ///< outside any frame
    };

    explicit V2Decoder(OnFrame on_frame, OnError on_error = {});

    void receive(std::span<const std::uint8_t> bytes);
    /// Whether a frame has begun (0x90 seen) and is not whole yet.
    bool mid_frame() const { return stage_ != Stage::Hunting; }
    void on_timeout();

    const Counters& counters() const { return counters_; }

private:
    enum class Stage {
        Hunting,     ///< outside a frame, looking for 0x90
        SyncStarted, ///< outside a frame, 0x90 seen
        OpCode,
        Len,
        Data,
        CrcLow,
        CrcHigh,
    };

    void receive_byte(std::uint8_t byte);
    void hunt(std::uint8_t byte);
    void take(std::uint8_t byte); ///< an unstuffed byte of the frame
    void start_frame();
    void drop(V2Error error);

    OnFrame on_frame_;
    OnError on_error_;
    Stage stage_ = Stage::Hunting;
    bool escaped_ = false; ///< inside a frame, the last byte was a 0x90 not yet paired
    Frame frame_;
    std::size_t expected_data_ = 0;
    std::uint16_t crc_ = 0;
    Counters counters_;
};

} // namespace eposp::service
