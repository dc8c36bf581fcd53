#include "eposp/service/v1_device_link.hpp"

#include <stdexcept>
#include <utility>

namespace eposp::service {

V1DeviceLink::V1DeviceLink(Write write, OnRequest on_request)
    : write_(std::move(write)), on_request_(std::move(on_request)) {}

void V1DeviceLink::receive(std::span<const std::uint8_t> bytes) {
    for (const std::uint8_t byte : bytes) {
        receive_byte(byte);
    }
}

void V1DeviceLink::receive_byte(std::uint8_t byte) {
    switch (stage_) {
    case Stage::Idle:
        if (!is_v1_request_opcode(byte)) {
            ++counters_.ignored_bytes;
            return;
        }
        reader_.emplace(byte);
        stage_ = Stage::ReceivingRequest;
        write_byte(kReady);
        return;
    case Stage::ReceivingRequest:
        switch (reader_->push(byte)) {
        case V1FrameReader::Status::Incomplete:
            return;
        case V1FrameReader::Status::BadCrc:
            // Guide: the receiver answers 'F' to a wrong CRC and drops the frame.
            ++counters_.crc_errors;
            reader_.reset();
            stage_ = Stage::Idle;
            write_byte(kNotReady);
            return;
        case V1FrameReader::Status::Complete: {
            const Frame request = std::move(*reader_).take();
            reader_.reset();
            ++counters_.requests;
            stage_ = Stage::Processing;
            write_byte(kReady);
            on_request_(request);
            return;
        }
        }
        return;
    case Stage::Processing:
        refuse_if_opcode(byte);
        return;
    case Stage::AnswerOpcodeSent:
    case Stage::AnswerSent:
        answer_handshake(byte);
        return;
    }
}

// The host's handshake to the answer: 'O' goes on, 'F' loses the answer (nothing is resent:
// maxon's hosts start a new request after a 'F'), an opcode is refused while the answer waits.
void V1DeviceLink::answer_handshake(std::uint8_t byte) {
    if (byte == kNotReady) {
        ++counters_.answers_lost;
        answer_rest_.clear();
        stage_ = Stage::Idle;
        return;
    }
    if (byte != kReady) {
        refuse_if_opcode(byte);
        return;
    }
    if (stage_ == Stage::AnswerOpcodeSent) {
        stage_ = Stage::AnswerSent;
        // Moved out first: the host's 'O' may come back from within write_().
        const std::vector<std::uint8_t> rest = std::exchange(answer_rest_, {});
        write_(rest);
        return;
    }
    ++counters_.answers_sent;
    stage_ = Stage::Idle;
}

void V1DeviceLink::refuse_if_opcode(std::uint8_t byte) {
    if (!is_v1_request_opcode(byte)) {
        ++counters_.ignored_bytes;
        return;
    }
    ++counters_.refused_busy;
    write_byte(kNotReady);
}

void V1DeviceLink::send_answer(const Frame& answer) {
    if (stage_ != Stage::Processing) {
        throw std::logic_error("V1DeviceLink::send_answer without a request awaiting its answer");
    }
    answer_rest_ = v1_frame_rest(answer); // throws for a frame v1 cannot carry
    stage_ = Stage::AnswerOpcodeSent;
    write_byte(kAnswerOpCode);
}

void V1DeviceLink::skip_answer() {
    if (stage_ != Stage::Processing) {
        throw std::logic_error("V1DeviceLink::skip_answer without a request awaiting its answer");
    }
    stage_ = Stage::Idle;
}

bool V1DeviceLink::mid_frame() const {
    return stage_ == Stage::ReceivingRequest || stage_ == Stage::AnswerOpcodeSent ||
           stage_ == Stage::AnswerSent;
}

void V1DeviceLink::on_timeout() {
    if (!mid_frame()) {
        return;
    }
    ++counters_.timeouts;
    if (stage_ != Stage::ReceivingRequest) {
        ++counters_.answers_lost;
    }
    reader_.reset();
    answer_rest_.clear();
    stage_ = Stage::Idle;
}

void V1DeviceLink::write_byte(std::uint8_t byte) {
    write_(std::span<const std::uint8_t>(&byte, 1));
}

} // namespace eposp::service
