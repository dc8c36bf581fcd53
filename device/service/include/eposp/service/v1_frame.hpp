#pragma once

#include "eposp/service/frame.hpp"

#include <cstdint>
#include <vector>

namespace eposp::service {

/// The handshake bytes of the RS-232 link (v1), maxon EPOS2 communication guide, "RS232
/// protocol": the receiver of an opcode answers kReady ('O', ready) or kNotReady ('F', not
/// ready); the receiver of the rest of the frame answers kReady (CRC right) or kNotReady (CRC
/// wrong: the frame is dropped).
inline constexpr std::uint8_t kReady = 0x4F;
inline constexpr std::uint8_t kNotReady = 0x46;

/// Whether `byte` may open a request on v1: not the answer opcode 0x00 and not a handshake byte
/// (no command has opcode 0x46 or 0x4F), so stray handshakes are never taken for a request.
bool is_v1_request_opcode(std::uint8_t byte);

/// What follows the opcode and its handshake on v1: Len-1, the data words low byte first, the
/// CRC low byte first. Throws std::invalid_argument for a frame of 0 or more than 256 words.
std::vector<std::uint8_t> v1_frame_rest(const Frame& frame);

/// Reads what follows an opcode on v1 (Len-1, data, CRC) byte by byte. At most 2 + 512 + 2
/// bytes are ever buffered.
class V1FrameReader {
public:
    enum class Status {
        Incomplete, ///< more bytes to come
        Complete,   ///< the frame is whole and its CRC right: take() it
        BadCrc,     ///< the frame is whole and its CRC wrong
    };

    explicit V1FrameReader(std::uint8_t opcode) { frame_.opcode = opcode; }

    /// Takes the next byte; after Complete or BadCrc the reader takes no more.
    Status push(std::uint8_t byte);
    Frame take() && { return std::move(frame_); }

private:
    Frame frame_;
    std::size_t expected_data_ = 0; ///< bytes, known once Len-1 arrived
    bool have_length_ = false;
    std::uint16_t crc_ = 0;
    int crc_bytes_ = 0;
};

} // namespace eposp::service
