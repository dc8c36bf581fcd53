// What a socketcand client may send, as arbitrary bytes arriving in arbitrary TCP segments:
// the server's framing and command parser (socketcand_protocol.hpp) never crash, find the same
// messages however the bytes are segmented, the errors it answers stay one message, and what
// goes on the bus is the frame sent or, for an empty one, the guard request it stands for.

#include "eposp/can/io/socketcand_protocol.hpp"
#include "fuzz_check.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace {

namespace sc = eposp::can::io::socketcand;
using eposp::fuzz::require;

/// Replies are not bound by the length limit on what clients send, only by the brackets.
void check_error_reply(std::string_view reason) {
    const std::string reply = sc::format_error(reason);
    const std::string_view inside = std::string_view(reply).substr(1, reply.size() - 2);
    require(reply.front() == '<' && reply.back() == '>' &&
                inside.find_first_of("<>") == std::string_view::npos,
            "an error reply is one message");
}

void check_command(const sc::Command& command) {
    std::visit(
        [](const auto& parsed) {
            using T = std::decay_t<decltype(parsed)>;
            if constexpr (std::is_same_v<T, sc::SendFrame>) {
                require(parsed.frame.valid(), "a frame to send is valid");
                const sc::Command again = sc::parse_command(sc::format_send(parsed.frame));
                const auto* send = std::get_if<sc::SendFrame>(&again);
                require(send != nullptr && send->frame == parsed.frame,
                        "a frame to send formats as a send that reads back to it");
                const eposp::can::Frame on_bus = sc::frame_for_bus(parsed.frame);
                require(on_bus.valid() &&
                            (on_bus == parsed.frame ||
                             (on_bus.remote && !parsed.frame.remote && parsed.frame.dlc == 0 &&
                              on_bus.id == parsed.frame.id && !on_bus.extended)),
                        "the bus gets the frame as sent, or an empty one as the guard request");
            } else if constexpr (std::is_same_v<T, sc::OpenBus>) {
                require(parsed.bus.size() <= sc::kMaxBusNameLength, "a bus name is short");
                check_error_reply(parsed.bus); // the server names the bus in its refusal
            } else if constexpr (std::is_same_v<T, sc::Malformed>) {
                check_error_reply(parsed.reason);
            } else if constexpr (std::is_same_v<T, sc::Unknown> ||
                                 std::is_same_v<T, sc::NotSupported>) {
                check_error_reply(parsed.name);
            }
        },
        command);
}

/// The messages the server finds in `stream` arriving `segment` bytes at a time, processed the
/// way a session does it: up to garbage or a message too long, which end the connection.
std::vector<std::string> messages(std::string_view stream, std::size_t segment) {
    std::vector<std::string> found;
    std::string input;
    for (std::size_t at = 0; at < stream.size(); at += segment) {
        input.append(stream.substr(at, segment));
        for (;;) {
            const sc::Scan scan = sc::scan_message(input);
            require(scan.consumed <= input.size(), "a scan consumes bytes it has");
            if (scan.kind == sc::Scan::Kind::Message) {
                require(scan.message.size() <= sc::kMaxMessageLength &&
                            scan.message.front() == '<' && scan.message.back() == '>' &&
                            scan.consumed >= scan.message.size(),
                        "a message is bracketed, not too long and consumed");
                check_command(sc::parse_command(scan.message));
                found.emplace_back(scan.message);
                input.erase(0, scan.consumed);
            } else if (scan.kind == sc::Scan::Kind::Incomplete) {
                input.erase(0, scan.consumed);
                break;
            } else {
                found.emplace_back(scan.kind == sc::Scan::Kind::Garbage ? "garbage" : "too long");
                return found;
            }
        }
    }
    return found;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return 0;
    }
    // The first byte chooses the segment size; the rest is what the client sends.
    const std::size_t segment = data[0] % 16u + 1u;
    const std::string_view stream(reinterpret_cast<const char*>(data + 1), size - 1);
    require(messages(stream, segment) == messages(stream, std::max<std::size_t>(stream.size(), 1)),
            "the messages found do not depend on how the bytes are segmented");
    return 0;
}
