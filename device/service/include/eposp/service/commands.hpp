#pragma once

#include "eposp/service/frame.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace eposp::service {

/// The commands of maxon's serial protocols (EPOS2 communication guide, "Command reference"),
/// the same on both links. The plain ones address node `NodeId` (0: the device itself, other
/// values: that node on the CAN port, through the gateway); the network-addressed ones of the
/// EPOS2 P generation (0x40 - 0x55, v2) name the network first: 0 the controller itself, 1 its
/// internal port, 2 its external CAN port.
enum class OpCode : std::uint8_t {
    SendNmtService = 0x0E,
    ReadObject = 0x10,
    WriteObject = 0x11,
    InitiateSegmentedRead = 0x12,
    InitiateSegmentedWrite = 0x13,
    SegmentRead = 0x14,
    SegmentWrite = 0x15,
    SendCanFrame = 0x20,
    RequestCanFrame = 0x21,
    SendLssFrame = 0x30,
    ReadLssFrame = 0x31,
    NetworkReadObject = 0x40,
    NetworkInitiateSegmentedRead = 0x41,
    NetworkSegmentRead = 0x42,
    NetworkWriteObject = 0x48,
    NetworkInitiateSegmentedWrite = 0x49,
    NetworkSegmentWrite = 0x4A,
    NetworkSendNmtService = 0x4B,
    NetworkSendCanFrame = 0x50,
    NetworkRequestCanFrame = 0x51,
    NetworkSendLssFrame = 0x54,
    NetworkReadLssFrame = 0x55,
};

/// The communication error codes an answer carries besides the CANopen abort codes.
namespace error {
inline constexpr std::uint32_t kNone = 0;
inline constexpr std::uint32_t kIllegalCommand = 0x0F00FFBF; ///< unknown operation code
inline constexpr std::uint32_t kWrongNodeId = 0x0F00FFB9;
inline constexpr std::uint32_t kWrongNmtState = 0x0F00FFC0;
/// The parameters do not have the command's length (CiA 301: "length of service parameter does
/// not match").
inline constexpr std::uint32_t kLengthMismatch = 0x06070010;
/// ESCON2 FW spec table 111: a ReadObject of a value that needs a segmented read.
inline constexpr std::uint32_t kSegmentedTransferExpected = 0x0F00FFC1;
} // namespace error

/// Which network a request addresses: kDevice (the plain opcodes; NodeId 0 is the device,
/// others the CAN port) or the NetworkId of a network-addressed opcode.
enum class Network : std::uint16_t { Controller = 0, InternalPort = 1, ExternalPort = 2 };

struct ObjectAddress {
    std::optional<Network> network; ///< empty: a plain opcode
    std::uint8_t node = 0;
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    friend bool operator==(const ObjectAddress&, const ObjectAddress&) = default;
};

/// Segment control byte: bits 0 - 5 the length (at most 63), bit 6 the toggle, bit 7 "more
/// segments follow".
struct SegmentControl {
    static constexpr std::size_t kMaxLength = 63;
    std::uint8_t length = 0;
    bool toggle = false;
    bool more = false;
    std::uint8_t encode() const;
    static SegmentControl decode(std::uint8_t byte);
    friend bool operator==(const SegmentControl&, const SegmentControl&) = default;
};

struct ReadObject {
    ObjectAddress object;
};
struct WriteObject {
    ObjectAddress object;
    std::array<std::uint8_t, 4> value{};
};
struct InitiateSegmentedRead {
    ObjectAddress object;
};
struct InitiateSegmentedWrite {
    ObjectAddress object;
    std::uint32_t length = 0;
};
struct SegmentRead {
    std::optional<Network> network;
    bool toggle = false;
};
struct SegmentWrite {
    std::optional<Network> network;
    SegmentControl control;
    std::vector<std::uint8_t> data; ///< control.length bytes
};
struct SendNmtService {
    std::optional<Network> network;
    std::uint16_t node = 0; ///< 0: every node
    std::uint16_t command = 0;
};
struct SendCanFrame {
    std::optional<Network> network;
    std::uint16_t cob_id = 0;
    std::uint16_t length = 0;
    std::array<std::uint8_t, 8> data{};
};
/// Sends a remote frame and answers with the data of the frame that answers it.
struct RequestCanFrame {
    std::optional<Network> network;
    std::uint16_t cob_id = 0;
    std::uint16_t length = 0;
};
struct SendLssFrame {
    std::optional<Network> network;
    std::array<std::uint8_t, 8> data{};
};
/// Answers with the next LSS response (0x7E4) within `timeout_ms`.
struct ReadLssFrame {
    std::optional<Network> network;
    std::uint16_t timeout_ms = 0;
};

using Request = std::variant<ReadObject, WriteObject, InitiateSegmentedRead, InitiateSegmentedWrite,
                             SegmentRead, SegmentWrite, SendNmtService, SendCanFrame,
                             RequestCanFrame, SendLssFrame, ReadLssFrame>;

/// A request frame decoded, or the communication error code its answer carries
/// (kIllegalCommand, kLengthMismatch).
struct DecodedRequest {
    std::optional<Request> request;
    std::uint32_t error = error::kNone;
};
DecodedRequest decode_request(const Frame& frame);
Frame encode_request(const Request& request);

/// Whether a link that has the protocol of RS-232 (v1) answers this request: it does not
/// answer SendNMTService, SendCANFrame and SendLSSFrame.
bool answered_on_v1(std::uint8_t opcode);

/// An answer: the error code (0: done), then the command's data, padded to whole words.
struct Answer {
    std::uint32_t error = error::kNone;
    std::vector<std::uint8_t> data;
    friend bool operator==(const Answer&, const Answer&) = default;
};
Frame encode_answer(const Answer& answer);
/// The answer in a frame; empty when it is shorter than the error code.
std::optional<Answer> decode_answer(const Frame& frame);

} // namespace eposp::service
