#pragma once

// The RS-232 (v1) vectors of issue 14, for the device side's and the host side's tests: ReadObject
// 0x6041/0 of node 0 and its answer (error 0, value 0x00000637), each as its frame and as what
// follows the opcode on the line (Len-1, data, CRC).

#include "eposp/service/frame.hpp"
#include "random_frame.hpp"

namespace eposp::service::test {

inline const Frame kReadStatusword{0x10, bytes({0x41, 0x60, 0x00, 0x00})};
inline const Bytes kReadStatuswordRest = bytes({0x01, 0x41, 0x60, 0x00, 0x00, 0x9A, 0xC3});
inline const Frame kAnswer{0x00, bytes({0, 0, 0, 0, 0x37, 0x06, 0, 0})};
inline const Bytes kAnswerRest =
    bytes({0x03, 0x00, 0x00, 0x00, 0x00, 0x37, 0x06, 0x00, 0x00, 0xE8, 0x4A});

} // namespace eposp::service::test
