#include "eposp/service/v1_host_link.hpp"

#include <stdexcept>
#include <utility>

namespace eposp::service {

V1HostLink::V1HostLink(Write write, OnComplete on_complete)
    : write_(std::move(write)), on_complete_(std::move(on_complete)) {}

void V1HostLink::request(const Frame& frame, bool expect_answer) {
    if (busy()) {
        throw std::logic_error("V1HostLink::request while a request is outstanding");
    }
    rest_ = v1_frame_rest(frame); // throws for a frame v1 cannot carry
    expect_answer_ = expect_answer;
    stage_ = Stage::AwaitReady;
    write_byte(frame.opcode);
}

void V1HostLink::receive(std::span<const std::uint8_t> bytes) {
    for (const std::uint8_t byte : bytes) {
        receive_byte(byte);
    }
}

void V1HostLink::receive_byte(std::uint8_t byte) {
    switch (stage_) {
    case Stage::Idle:
        ++stray_bytes_;
        return;
    case Stage::AwaitReady:
        if (byte == kReady) {
            stage_ = Stage::AwaitFrameAck;
            // Moved out first: the device's 'O' may come back from within write_().
            const std::vector<std::uint8_t> rest = std::exchange(rest_, {});
            write_(rest);
        } else {
            complete(byte == kNotReady ? V1Outcome::DeviceNotReady : V1Outcome::UnexpectedByte);
        }
        return;
    case Stage::AwaitFrameAck:
        if (byte == kReady) {
            if (expect_answer_) {
                stage_ = Stage::AwaitAnswerOpcode;
            } else {
                complete(V1Outcome::Sent);
            }
        } else {
            complete(byte == kNotReady ? V1Outcome::DeviceCrcError : V1Outcome::UnexpectedByte);
        }
        return;
    case Stage::AwaitAnswerOpcode:
        if (byte != kAnswerOpCode) {
            complete(V1Outcome::UnexpectedByte);
            return;
        }
        reader_.emplace(kAnswerOpCode);
        stage_ = Stage::ReceivingAnswer;
        write_byte(kReady);
        return;
    case Stage::ReceivingAnswer:
        receive_answer_byte(byte);
        return;
    }
}

void V1HostLink::receive_answer_byte(std::uint8_t byte) {
    switch (reader_->push(byte)) {
    case V1FrameReader::Status::Incomplete:
        return;
    case V1FrameReader::Status::BadCrc:
        // Guide: 'F' to a wrong CRC; the device sends nothing again.
        acknowledge_and_complete(kNotReady, V1Outcome::AnswerCrcError);
        return;
    case V1FrameReader::Status::Complete: {
        Frame answer = std::move(*reader_).take();
        acknowledge_and_complete(kReady, V1Outcome::Answered, std::move(answer));
        return;
    }
    }
}

void V1HostLink::on_timeout() {
    if (busy()) {
        complete(V1Outcome::Timeout);
    }
}

// Idle before the callback, so that it may send the next request.
void V1HostLink::complete(V1Outcome outcome) {
    stage_ = Stage::Idle;
    rest_.clear();
    reader_.reset();
    on_complete_(V1Completion{outcome, std::nullopt});
}

// Idle before the handshake is written (bytes may come back from within write_()), the
// handshake before the callback (which may write the next request's opcode).
void V1HostLink::acknowledge_and_complete(std::uint8_t handshake, V1Outcome outcome,
                                          std::optional<Frame> answer) {
    stage_ = Stage::Idle;
    reader_.reset();
    write_byte(handshake);
    on_complete_(V1Completion{outcome, std::move(answer)});
}

void V1HostLink::write_byte(std::uint8_t byte) {
    write_(std::span<const std::uint8_t>(&byte, 1));
}

} // namespace eposp::service
