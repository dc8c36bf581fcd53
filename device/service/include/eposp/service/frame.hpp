#pragma once

#include <cstdint>
#include <vector>

namespace eposp::service {

/// One frame of maxon's serial protocols as both links carry it (docs/service-interface.md):
/// an operation code and its parameters, a whole number of 16-bit words sent low byte first.
/// The links differ only in how a frame is framed (v1: handshakes and Len-1; v2: 0x90 0x02
/// with byte stuffing), not in what it holds.
struct Frame {
    std::uint8_t opcode = 0;
    std::vector<std::uint8_t> data; ///< even length: the data words, little-endian

    std::size_t words() const { return data.size() / 2; }
    friend bool operator==(const Frame&, const Frame&) = default;
};

/// The operation code of every answer.
inline constexpr std::uint8_t kAnswerOpCode = 0x00;

} // namespace eposp::service
