#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/canopen/abort_code.hpp"
#include "eposp/canopen/nmt_state.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

// The SDO messages of CiA 301 7.2.4.3 as bytes: what the SDO server and the SDO client share.
// Byte 0 of every message is its command; bits 7..5 are the command specifier.
namespace eposp::canopen::sdo {

/// Every SDO message is a data frame of 8 bytes (CiA 301 7.2.4.3.1).
inline constexpr std::size_t kMessageSize = 8;
/// Up to this many bytes go in the initiate message itself (expedited transfer).
inline constexpr std::size_t kExpeditedSize = 4;
/// Data bytes in a segment of a segmented or block transfer.
inline constexpr std::size_t kSegmentSize = 7;
/// Segments per block: 1..127 (CiA 301 7.2.4.3.9, blksize).
inline constexpr std::uint8_t kMaxBlockSize = 127;

using Message = std::array<std::uint8_t, kMessageSize>;

/// Client command specifiers (ccs): bits 7..5 of byte 0 from client to server.
namespace ccs {
inline constexpr std::uint8_t kDownloadSegment = 0;
inline constexpr std::uint8_t kInitiateDownload = 1;
inline constexpr std::uint8_t kInitiateUpload = 2;
inline constexpr std::uint8_t kUploadSegment = 3;
inline constexpr std::uint8_t kBlockUpload = 5;
inline constexpr std::uint8_t kBlockDownload = 6;
} // namespace ccs

/// Server command specifiers (scs): bits 7..5 of byte 0 from server to client.
namespace scs {
inline constexpr std::uint8_t kUploadSegment = 0;
inline constexpr std::uint8_t kDownloadSegment = 1;
inline constexpr std::uint8_t kInitiateUpload = 2;
inline constexpr std::uint8_t kInitiateDownload = 3;
inline constexpr std::uint8_t kBlockDownload = 5;
inline constexpr std::uint8_t kBlockUpload = 6;
} // namespace scs

/// The abort specifier, the same in both directions (CiA 301 7.2.4.3.17).
inline constexpr std::uint8_t kAbort = 4;
/// Byte 0 of an abort message. In a sub-block only this byte is an abort (seqno 0 with c set):
/// other bytes with specifier 4 are segments 1..31 with c set.
inline constexpr std::uint8_t kAbortCommand = kAbort << 5;

/// Sub-commands of the block protocols (cs / ss, bits 1..0 of byte 0).
namespace block {
inline constexpr std::uint8_t kInitiate = 0;
inline constexpr std::uint8_t kEnd = 1;
inline constexpr std::uint8_t kAcknowledge = 2; ///< "block download/upload response"
inline constexpr std::uint8_t kStartUpload = 3;
} // namespace block

inline constexpr std::uint8_t command_specifier(std::uint8_t byte0) {
    return static_cast<std::uint8_t>(byte0 >> 5);
}
/// The sub-command of a block message: bit 0 under specifier 6 (block download requests, block
/// upload responses: bit 1 is their size indicator), bits 1..0 under specifier 5.
inline constexpr std::uint8_t block_subcommand(std::uint8_t byte0) {
    return static_cast<std::uint8_t>(byte0 & (command_specifier(byte0) == 6 ? 0x01 : 0x03));
}

// Byte 0 of each kind of message. `unused` is n, the number of trailing bytes that carry no
// data.

/// Initiate download request (ccs 1) and initiate upload response (scs 2): n in bits 3..2,
/// e (expedited) in bit 1, s (size indicated) in bit 0.
inline constexpr std::uint8_t initiate_command(std::uint8_t specifier, std::size_t unused,
                                               bool expedited, bool size_indicated) {
    return static_cast<std::uint8_t>(specifier << 5 | (unused & 0x3) << 2 | (expedited ? 2 : 0) |
                                     (size_indicated ? 1 : 0));
}
/// Segments of segmented transfers (ccs 0, scs 0) and their responses (scs 1, ccs 3): t
/// (toggle) in bit 4, n in bits 3..1, c (last segment) in bit 0.
inline constexpr std::uint8_t segment_command(std::uint8_t specifier, bool toggle,
                                              std::size_t unused = 0, bool last = false) {
    return static_cast<std::uint8_t>(specifier << 5 | (toggle ? 0x10 : 0) | (unused & 0x7) << 1 |
                                     (last ? 1 : 0));
}
/// Block initiate messages: crc support in bit 2, size indicated in bit 1.
inline constexpr std::uint8_t block_initiate_command(std::uint8_t specifier, bool crc,
                                                     bool size_indicated = false) {
    return static_cast<std::uint8_t>(specifier << 5 | (crc ? 4 : 0) | (size_indicated ? 2 : 0) |
                                     block::kInitiate);
}
/// Block end messages: n of the last segment in bits 4..2.
inline constexpr std::uint8_t block_end_command(std::uint8_t specifier, std::size_t unused = 0) {
    return static_cast<std::uint8_t>(specifier << 5 | (unused & 0x7) << 2 | block::kEnd);
}
inline constexpr std::uint8_t block_command(std::uint8_t specifier, std::uint8_t subcommand) {
    return static_cast<std::uint8_t>(specifier << 5 | subcommand);
}
/// A segment of a sub-block: c (last segment of the transfer) in bit 7, seqno 1..127 below.
inline constexpr std::uint8_t block_segment_command(std::uint8_t sequence, bool last) {
    return static_cast<std::uint8_t>((last ? 0x80 : 0) | (sequence & 0x7F));
}

inline constexpr bool toggle_of(std::uint8_t byte0) {
    return (byte0 & 0x10) != 0;
}

/// The object a transfer addresses: index and sub-index, bytes 1..3 of the initiate messages.
struct Multiplexer {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    friend bool operator==(const Multiplexer&, const Multiplexer&) = default;
};

/// A message with a command, a multiplexer and a 32-bit value in bytes 4..7 (a size, an abort
/// code, or expedited data read as little-endian).
Message message(std::uint8_t command, Multiplexer mux, std::uint32_t value = 0);
/// A message with a command and up to 7 data bytes after it (segments).
Message segment_message(std::uint8_t command, std::span<const std::uint8_t> data);
Message abort_message(Multiplexer mux, AbortCode code);

/// Bytes 1..3 of a message.
Multiplexer multiplexer_of(std::span<const std::uint8_t, kMessageSize> bytes);
/// Bytes 4..7 of a message, little-endian.
std::uint32_t value_of(std::span<const std::uint8_t, kMessageSize> bytes);

/// The COB-IDs of the default SDO of a node (CiA 301 7.3.5, pre-defined connection set).
inline constexpr std::uint32_t default_request_cob_id(NodeId node) {
    return 0x600U + node;
}
inline constexpr std::uint32_t default_response_cob_id(NodeId node) {
    return 0x580U + node;
}

/// True for an SDO message on `cob_id` (a COB-ID entry, cob_id.hpp): a data frame with that
/// identifier and format and 8 bytes. Frames of another length are not SDO messages and are
/// ignored, as CANopenNode does.
bool is_message_on(const can::Frame& frame, std::uint32_t cob_id);
/// The message's bytes; only for frames that is_message_on() accepted.
std::span<const std::uint8_t, kMessageSize> bytes_of(const can::Frame& frame);

/// The CRC of block transfers (CiA 301 7.2.4.3.16): CRC-16-CCITT, polynomial
/// x^16 + x^12 + x^5 + 1, initial value 0, neither reflected nor inverted.
std::uint16_t block_crc(std::span<const std::uint8_t> data);

} // namespace eposp::canopen::sdo
