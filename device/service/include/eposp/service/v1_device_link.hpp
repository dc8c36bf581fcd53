#pragma once

#include "eposp/service/frame.hpp"
#include "eposp/service/v1_frame.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace eposp::service {

/// The device side of the RS-232 link (v1) as a state machine: bytes from the host go in through
/// receive(), handshakes and answers go out through the write callback, each whole request with
/// a right CRC goes to the request callback (maxon EPOS2 communication guide, "RS232 protocol").
///
/// One exchange: host opcode → 'O'; host Len-1, data, CRC → 'O' (or 'F': CRC wrong, the request
/// is dropped); the request is delivered and the device is busy until the owner calls
/// send_answer() (opcode 0x00 → host 'O'; Len-1, data, CRC → host 'O') or skip_answer() (v1
/// sends no answer to SendNMTService, SendCANFrame, SendLSSFrame: answered_on_v1()).
///
/// Where the guide is silent (docs/service-interface.md, "Links and framing"):
/// - a request opcode while the device is busy (a request delivered and not yet answered, or an
///   answer not yet acknowledged) is refused with 'F' (not ready) and otherwise ignored;
/// - 0x00, 'O' and 'F' are never taken for a request opcode: they are ignored while idle;
/// - the host's 'F' to the answer opcode (not ready) or to the rest of the answer (CRC wrong)
///   loses the answer: nothing is sent again, as maxon's hosts then start a new request and a
///   resent answer would arrive at them as garbage;
/// - the frame timeout (object 0x5005) is the owner's: while mid_frame() it arms a timer
///   (restarted at each byte received) and calls on_timeout() when it expires; the frame or
///   answer in progress is dropped and the device waits for an opcode again.
class V1DeviceLink {
public:
    using Write = std::function<void(std::span<const std::uint8_t>)>;
    using OnRequest = std::function<void(const Frame&)>;

    struct Counters {
        std::uint64_t requests = 0;      ///< delivered to the owner
        std::uint64_t crc_errors = 0;    ///< requests dropped for their CRC ('F' sent)
        std::uint64_t refused_busy = 0;  ///< opcodes refused with 'F' while busy
        std::uint64_t answers_sent = 0;  ///< acknowledged by the host
        std::uint64_t answers_lost = 0;  ///< the host said 'F' or timed out
        std::uint64_t timeouts = 0;      ///< on_timeout() mid-frame
        std::uint64_t ignored_bytes = 0; ///< 0x00 / 'O' / 'F' while idle, stray bytes
    };

    V1DeviceLink(Write write, OnRequest on_request);

    void receive(std::span<const std::uint8_t> bytes);
    /// Answers the request delivered last. A programming error (std::logic_error) when no
    /// request awaits its answer, std::invalid_argument for a frame of 0 or more than 256 words.
    void send_answer(const Frame& answer);
    /// Ends the request delivered last without an answer.
    void skip_answer();

    /// Whether a frame is being received or an answer waits for the host: the frame timeout
    /// runs. Not while a request is with the owner: it takes the time it needs.
    bool mid_frame() const;
    /// Whether a delivered request waits for send_answer() or skip_answer().
    bool awaiting_answer() const { return stage_ == Stage::Processing; }
    void on_timeout();

    const Counters& counters() const { return counters_; }

private:
    enum class Stage {
        Idle,
        ReceivingRequest, ///< opcode acknowledged; Len-1, data, CRC arriving
        Processing,       ///< the request is with the owner
        AnswerOpcodeSent, ///< waiting for the host's 'O' to opcode 0x00
        AnswerSent,       ///< waiting for the host's 'O' to the rest of the answer
    };

    void receive_byte(std::uint8_t byte);
    void write_byte(std::uint8_t byte);
    void answer_handshake(std::uint8_t byte);
    void refuse_if_opcode(std::uint8_t byte);

    Write write_;
    OnRequest on_request_;
    Stage stage_ = Stage::Idle;
    std::optional<V1FrameReader> reader_;
    std::vector<std::uint8_t> answer_rest_; ///< Len-1, data, CRC until the host is ready
    Counters counters_;
};

} // namespace eposp::service
