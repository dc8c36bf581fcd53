#pragma once

// The socketcand protocol (linux-can/socketcand, doc/protocol.md) as pure functions: splitting
// the TCP byte stream into `< ... >` messages, parsing what a client sends, and formatting what
// a server sends. No I/O here, so every function can be table-tested and fuzzed.

#include "eposp/can/frame.hpp"
#include "eposp/core/time.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <variant>

namespace eposp::can::io::socketcand {

/// The longest message accepted from a client, brackets included. The longest valid one, a
/// `send` of an extended frame with eight bytes, has 43 characters; the rest is room for
/// extra spaces. A client takes the same limit for what a server sends (its longest frame
/// message has 52 characters).
inline constexpr std::size_t kMaxMessageLength = 128;
/// protocol.md, mode NO_BUS: "canbus may be at maximum 16 characters long".
inline constexpr std::size_t kMaxBusNameLength = 16;

inline constexpr std::string_view kHi = "< hi >";
inline constexpr std::string_view kOk = "< ok >";
inline constexpr std::string_view kEcho = "< echo >";

// ---- Framing ----------------------------------------------------------------------------------

/// The first message in a receive buffer, or why there is none.
struct Scan {
    enum class Kind {
        Message,    ///< `message` is complete; drop `consumed` bytes from the buffer
        Incomplete, ///< wait for more bytes; `consumed` bytes of whitespace may be dropped
        Garbage,    ///< bytes outside a message that are not whitespace, or a '<' inside one
        TooLong,    ///< a message longer than kMaxMessageLength
    };
    Kind kind = Kind::Incomplete;
    std::string_view message; ///< from '<' to '>', both included
    std::size_t consumed = 0;
};

/// Finds the first message in `buffer`. Whitespace between messages is skipped (clients that
/// type into netcat end their messages with newlines).
Scan scan_message(std::string_view buffer);

// ---- What a client sends ----------------------------------------------------------------------

/// `< open BUS >`
struct OpenBus {
    std::string bus;
};
/// The modes of protocol.md; a session starts in NoBus and `open` moves it to Bcm.
enum class Mode { Bcm, Raw, Control, IsoTp };
std::string_view to_string(Mode mode);
/// `< rawmode >`, `< bcmmode >`, `< controlmode >`, `< isotpmode >`
struct SwitchMode {
    Mode mode = Mode::Raw;
};
/// `< echo >`: the server answers with the same message.
struct Echo {};
/// `< send ID DLC BYTE... >` or `< sendrtr ID DLC >`. The identifier is extended when written
/// with 8 hex digits (socketcand's rule, state_raw.c), standard when written with fewer and at
/// most 7FF, and extended beyond 7FF, which no standard identifier is: python-can 4.1 writes
/// extended identifiers without leading zeros. Beyond 1FFFFFFF it is malformed.
struct SendFrame {
    Frame frame;
};
/// A command of the protocol that this server does not serve (the BCM, ISO-TP and control
/// modes' commands, CAN FD).
struct NotSupported {
    std::string name;
};
/// A word that is no command of the protocol.
struct Unknown {
    std::string name;
};
/// A message that is not a well-formed command: what is wrong with it.
struct Malformed {
    std::string reason;
};

using Command =
    std::variant<OpenBus, SwitchMode, Echo, SendFrame, NotSupported, Unknown, Malformed>;

/// Parses one message as scan_message() delimits it, brackets included.
Command parse_command(std::string_view message);

/// What the server puts on the bus for a frame a client sends. socketcand's `send` has no RTR
/// flag, so python-can 4.1 sends a remote frame, e.g. python-canopen's node guard request, as
/// a data frame without data. A standard data frame without data on 0x701..0x77F is no other
/// CiA 301 message (boot-up and heartbeat carry one byte), so it is taken for the guard request
/// (CiA 301 7.2.8.3.2.1): a remote frame with DLC 1, the length of the answer. Any other frame
/// is put on the bus as sent.
Frame frame_for_bus(const Frame& sent);

/// The command a client sends to put `frame` on the bus (a data or a remote frame).
std::string format_send(const Frame& frame);

// ---- What a server sends ----------------------------------------------------------------------

/// `< error REASON >`; brackets in `reason` are replaced so the message stays one message.
std::string format_error(std::string_view reason);

/// A frame the bus carried, as raw mode reports it, stamped `since_epoch`:
/// `< frame ID SEC.USEC DATA >` with ID as 3 (standard) or 8 (extended) upper-case hex digits
/// and DATA the bytes as hex without spaces, like socketcand itself writes them; python-can
/// splits the message on spaces and reads DATA as one field, so an empty DATA still leaves
/// the space before it. Remote frames are `< rtr ID SEC.USEC DLC >`, error frames
/// `< error CLASS SEC.USEC >`.
std::string format_received(const Frame& frame, core::Duration since_epoch);

// ---- What a client receives -------------------------------------------------------------------

/// `< hi >`, the greeting on connect.
struct Hi {};
/// `< ok >`, the answer to `open` and to a mode switch.
struct Ok {};
/// `< frame ID SEC.USEC DATA >`, `< rtr ID SEC.USEC DLC >` or `< error CLASS SEC.USEC >` as
/// format_received() writes them (socketcand itself sends no remote frames). The identifier is
/// extended when written with 8 digits or when it does not fit 11 bits, as in a send.
struct ReceivedFrame {
    Frame frame;
    core::Duration since_epoch{};
};
/// `< error REASON >`: the server refused what the client asked for.
struct ErrorReply {
    std::string reason;
};

/// Unknown carries the first word of a message no server of the protocol sends in raw mode for a
/// classic CAN bus (e.g. socketcand's `fdframe`).
using ServerMessage = std::variant<Hi, Ok, Echo, ReceivedFrame, ErrorReply, Unknown, Malformed>;

/// Parses one message as scan_message() delimits it, brackets included.
ServerMessage parse_server_message(std::string_view message);

} // namespace eposp::can::io::socketcand
