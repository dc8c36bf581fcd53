#pragma once

#include "eposp/service/frame.hpp"
#include "eposp/service/v1_frame.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace eposp::service {

/// How a request on the RS-232 link (v1) ended.
enum class V1Outcome {
    Answered,       ///< the answer arrived with a right CRC (and was acknowledged with 'O')
    Sent,           ///< a request that gets no answer on v1 was acknowledged by the device
    DeviceNotReady, ///< the device answered the opcode with 'F'
    DeviceCrcError, ///< the device answered the frame with 'F' (it saw a wrong CRC)
    AnswerCrcError, ///< the answer's CRC was wrong (the host answered 'F')
    UnexpectedByte, ///< the device sent a byte that has no place in the exchange
    Timeout,        ///< on_timeout() while the request was outstanding
};

struct V1Completion {
    V1Outcome outcome = V1Outcome::Timeout;
    std::optional<Frame> answer; ///< with Answered only
};

/// The host side of the RS-232 link (v1) as a state machine, for the service clients (maxon
/// EPOS2 communication guide, "RS232 protocol"): request() writes the opcode, then on the
/// device's 'O' the rest of the frame; after the device's final 'O' it waits for the answer
/// (opcode 0x00 → 'O'; Len-1, data, CRC → 'O', or 'F' on a wrong CRC). Each request completes
/// exactly once through the completion callback; nothing is retried here (the client decides).
///
/// Time is the owner's: while busy() it arms a timer (restarted at each byte received; longer
/// while awaiting_answer(), when the device works on the request) and calls on_timeout().
class V1HostLink {
public:
    using Write = std::function<void(std::span<const std::uint8_t>)>;
    using OnComplete = std::function<void(const V1Completion&)>;

    V1HostLink(Write write, OnComplete on_complete);

    /// Sends `frame`; `expect_answer` false for the requests v1 does not answer
    /// (answered_on_v1()). A programming error (std::logic_error) while busy(),
    /// std::invalid_argument for a frame of 0 or more than 256 words.
    void request(const Frame& frame, bool expect_answer = true);
    void receive(std::span<const std::uint8_t> bytes);

    bool busy() const { return stage_ != Stage::Idle; }
    /// Whether the device took the request and the host waits for its answer to begin.
    bool awaiting_answer() const { return stage_ == Stage::AwaitAnswerOpcode; }
    void on_timeout();

    /// Bytes received while no request was outstanding (ignored).
    std::uint64_t stray_bytes() const { return stray_bytes_; }

private:
    enum class Stage {
        Idle,
        AwaitReady,        ///< opcode sent, waiting for 'O'
        AwaitFrameAck,     ///< Len-1, data, CRC sent, waiting for 'O'
        AwaitAnswerOpcode, ///< waiting for 0x00
        ReceivingAnswer,   ///< Len-1, data, CRC of the answer arriving
    };

    void receive_byte(std::uint8_t byte);
    void receive_answer_byte(std::uint8_t byte);
    void complete(V1Outcome outcome);
    void acknowledge_and_complete(std::uint8_t handshake, V1Outcome outcome,
                                  std::optional<Frame> answer = std::nullopt);
    void write_byte(std::uint8_t byte);

    Write write_;
    OnComplete on_complete_;
    Stage stage_ = Stage::Idle;
    bool expect_answer_ = true;
    std::vector<std::uint8_t> rest_; ///< Len-1, data, CRC of the request until the device is ready
    std::optional<V1FrameReader> reader_;
    std::uint64_t stray_bytes_ = 0;
};

} // namespace eposp::service
