#include "eposp/service/v2_decoder.hpp"

#include "eposp/service/crc.hpp"
#include "eposp/service/v2_encoder.hpp"

#include <utility>

namespace eposp::service {

V2Decoder::V2Decoder(OnFrame on_frame, OnError on_error)
    : on_frame_(std::move(on_frame)), on_error_(std::move(on_error)) {}

void V2Decoder::receive(std::span<const std::uint8_t> bytes) {
    for (const std::uint8_t byte : bytes) {
        receive_byte(byte);
    }
}

void V2Decoder::receive_byte(std::uint8_t byte) {
    if (stage_ == Stage::Hunting || stage_ == Stage::SyncStarted) {
        hunt(byte);
        return;
    }
    if (!escaped_) {
        if (byte == kV2Dle) {
            escaped_ = true;
        } else {
            take(byte);
        }
        return;
    }
    escaped_ = false;
    if (byte == kV2Dle) {
        take(kV2Dle);
    } else if (byte == kV2Stx) {
        drop(V2Error::Interrupted); // resynchronise on the new frame
        start_frame();
    } else {
        drop(V2Error::StuffingError);
    }
}

// Outside a frame 0x90 0x90 is taken as a stuffed data byte of a frame we missed the start of,
// so that 0x90 0x90 0x02 in its data does not look like a start.
void V2Decoder::hunt(std::uint8_t byte) {
    if (stage_ == Stage::Hunting) {
        if (byte == kV2Dle) {
            stage_ = Stage::SyncStarted;
        } else {
            ++counters_.skipped_bytes;
        }
        return;
    }
    if (byte == kV2Stx) {
        start_frame();
        return;
    }
    counters_.skipped_bytes += 2;
    stage_ = Stage::Hunting;
}

void V2Decoder::start_frame() {
    frame_ = Frame{};
    expected_data_ = 0;
    crc_ = 0;
    escaped_ = false;
    stage_ = Stage::OpCode;
}

void V2Decoder::take(std::uint8_t byte) {
    switch (stage_) {
    case Stage::OpCode:
        frame_.opcode = byte;
        stage_ = Stage::Len;
        return;
    case Stage::Len:
        expected_data_ = std::size_t{byte} * 2;
        frame_.data.reserve(expected_data_);
        stage_ = expected_data_ == 0 ? Stage::CrcLow : Stage::Data;
        return;
    case Stage::Data:
        frame_.data.push_back(byte);
        if (frame_.data.size() == expected_data_) {
            stage_ = Stage::CrcLow;
        }
        return;
    case Stage::CrcLow:
        crc_ = byte;
        stage_ = Stage::CrcHigh;
        return;
    case Stage::CrcHigh:
        crc_ = static_cast<std::uint16_t>(crc_ | byte << 8);
        if (crc_ != v2_crc(frame_)) {
            drop(V2Error::CrcError);
            return;
        }
        stage_ = Stage::Hunting;
        ++counters_.frames;
        on_frame_(std::exchange(frame_, Frame{}));
        return;
    case Stage::Hunting:
    case Stage::SyncStarted:
        return; // receive_byte() hunts instead
    }
}

void V2Decoder::on_timeout() {
    if (stage_ == Stage::SyncStarted) {
        stage_ = Stage::Hunting; // a lone 0x90, no frame yet
    } else if (mid_frame()) {
        drop(V2Error::Timeout);
    }
}

void V2Decoder::drop(V2Error error) {
    switch (error) {
    case V2Error::CrcError:
        ++counters_.crc_errors;
        break;
    case V2Error::StuffingError:
        ++counters_.stuffing_errors;
        break;
    case V2Error::Interrupted:
        ++counters_.interrupted;
        break;
    case V2Error::Timeout:
        ++counters_.timeouts;
        break;
    }
    frame_ = Frame{};
    escaped_ = false;
    stage_ = Stage::Hunting;
    if (on_error_) {
        on_error_(error);
    }
}

} // namespace eposp::service
