#include "eposp/can/io/socketcand_protocol.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <fmt/format.h>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace eposp::can::io::socketcand {
namespace {

constexpr std::string_view kWhitespace = " \t\r\n";

std::vector<std::string_view> split_fields(std::string_view text) {
    std::vector<std::string_view> fields;
    std::size_t pos = text.find_first_not_of(kWhitespace);
    while (pos != std::string_view::npos) {
        const std::size_t end = std::min(text.find_first_of(kWhitespace, pos), text.size());
        fields.push_back(text.substr(pos, end - pos));
        pos = text.find_first_not_of(kWhitespace, end);
    }
    return fields;
}

/// A hex number of 1..max_digits digits, nothing else (no sign, no 0x).
std::optional<std::uint32_t> parse_hex(std::string_view text, std::size_t max_digits) {
    if (text.empty() || text.size() > max_digits) {
        return std::nullopt;
    }
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, 16);
    if (error != std::errc{} || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return value;
}

struct Identifier {
    std::uint32_t id = 0;
    bool extended = false;
};

/// 1..8 hex digits; extended when written with 8 digits or beyond 11 bits (see SendFrame).
std::optional<Identifier> parse_identifier(std::string_view text) {
    constexpr std::size_t kExtendedIdDigits = 8;
    const auto id = parse_hex(text, kExtendedIdDigits);
    if (!id || *id > kMaxExtendedId) {
        return std::nullopt;
    }
    return Identifier{*id, text.size() == kExtendedIdDigits || *id > kMaxStandardId};
}

Command parse_send(std::span<const std::string_view> args, bool remote) {
    if (args.size() < 2) {
        return Malformed{"a send needs an identifier and a length"};
    }
    const auto identifier = parse_identifier(args[0]);
    if (!identifier) {
        return Malformed{"the identifier must be 1 to 8 hex digits up to 1FFFFFFF"};
    }
    const auto [id, extended] = *identifier;
    if (args[1].size() != 1 || args[1][0] < '0' || args[1][0] > '0' + kMaxDataLength) {
        return Malformed{"the length must be a digit 0 to 8"};
    }
    const auto dlc = static_cast<std::uint8_t>(args[1][0] - '0');
    const auto data_fields = args.subspan(2);
    if (remote) {
        if (!data_fields.empty()) {
            return Malformed{"a sendrtr carries no data bytes"};
        }
        return SendFrame{Frame::remote_frame(id, dlc, extended)};
    }
    if (data_fields.size() != dlc) {
        return Malformed{"the length does not match the number of data bytes"};
    }
    std::array<std::uint8_t, kMaxDataLength> bytes{};
    for (std::size_t i = 0; i < data_fields.size(); ++i) {
        const auto byte = parse_hex(data_fields[i], 2);
        if (!byte) {
            return Malformed{"a data byte must be 1 or 2 hex digits"};
        }
        bytes[i] = static_cast<std::uint8_t>(*byte);
    }
    return SendFrame{Frame::data_frame(id, std::span(bytes.data(), dlc), extended)};
}

std::optional<Mode> mode_named(std::string_view name) {
    if (name == "rawmode") {
        return Mode::Raw;
    }
    if (name == "bcmmode") {
        return Mode::Bcm;
    }
    if (name == "controlmode") {
        return Mode::Control;
    }
    if (name == "isotpmode") {
        return Mode::IsoTp;
    }
    return std::nullopt;
}

/// Commands of the BCM, CONTROL and ISO-TP modes and of CAN FD, which a raw-mode bridge of a
/// classic CAN bus does not serve.
bool is_unsupported_command(std::string_view name) {
    constexpr std::array<std::string_view, 11> kNames = {
        "add",         "update",     "delete",    "filter",  "muxfilter", "subscribe",
        "unsubscribe", "statistics", "isotpconf", "sendpdu", "fdsend"};
    return std::ranges::find(kNames, name) != kNames.end();
}

/// SEC.USEC as socketcand writes it (`%ld.%06ld`); 1 to 6 fraction digits are taken.
std::optional<core::Duration> parse_stamp(std::string_view text) {
    const std::size_t dot = text.find('.');
    if (dot == std::string_view::npos) {
        return std::nullopt;
    }
    const std::string_view whole = text.substr(0, dot);
    std::string fraction(text.substr(dot + 1));
    constexpr std::size_t kMicroDigits = 6;
    const auto digits = [](std::string_view s) {
        return !s.empty() && std::ranges::all_of(s, [](char c) { return c >= '0' && c <= '9'; });
    };
    if (!digits(whole) || !digits(fraction) || fraction.size() > kMicroDigits) {
        return std::nullopt;
    }
    fraction.resize(kMicroDigits, '0');
    std::int64_t seconds = 0;
    std::int64_t micros = 0;
    const auto parsed = std::from_chars(whole.data(), whole.data() + whole.size(), seconds);
    if (parsed.ec != std::errc{}) {
        return std::nullopt; // beyond 64 bits
    }
    std::from_chars(fraction.data(), fraction.data() + fraction.size(), micros);
    return std::chrono::seconds(seconds) + std::chrono::microseconds(micros);
}

/// `frame ID SEC.USEC DATA` with DATA as hex without spaces, absent when empty.
ServerMessage parse_frame(std::span<const std::string_view> args) {
    if (args.size() < 2 || args.size() > 3) {
        return Malformed{"a frame has an identifier, a time stamp and the data"};
    }
    const auto identifier = parse_identifier(args[0]);
    const auto stamp = parse_stamp(args[1]);
    const std::string_view data = args.size() == 3 ? args[2] : std::string_view{};
    if (!identifier || !stamp) {
        return Malformed{"a frame needs a hex identifier up to 1FFFFFFF and SEC.USEC"};
    }
    if (data.size() % 2 != 0 || data.size() > 2 * std::size_t{kMaxDataLength}) {
        return Malformed{"a frame's data must be 0 to 8 bytes as hex digit pairs"};
    }
    std::array<std::uint8_t, kMaxDataLength> bytes{};
    for (std::size_t i = 0; i < data.size() / 2; ++i) {
        const auto byte = parse_hex(data.substr(2 * i, 2), 2);
        if (!byte) {
            return Malformed{"a frame's data must be 0 to 8 bytes as hex digit pairs"};
        }
        bytes[i] = static_cast<std::uint8_t>(*byte);
    }
    return ReceivedFrame{Frame::data_frame(identifier->id, std::span(bytes.data(), data.size() / 2),
                                           identifier->extended),
                         *stamp};
}

/// `rtr ID SEC.USEC DLC`, as our server reports remote frames.
ServerMessage parse_remote(std::span<const std::string_view> args) {
    const auto identifier = args.size() == 3 ? parse_identifier(args[0]) : std::nullopt;
    const auto stamp = args.size() == 3 ? parse_stamp(args[1]) : std::nullopt;
    const auto dlc = args.size() == 3 ? parse_hex(args[2], 1) : std::nullopt;
    if (!identifier || !stamp || !dlc || *dlc > kMaxDataLength) {
        return Malformed{"a remote frame has an identifier, SEC.USEC and a length 0 to 8"};
    }
    return ReceivedFrame{
        Frame::remote_frame(identifier->id, static_cast<std::uint8_t>(*dlc), identifier->extended),
        *stamp};
}

/// `error CLASS SEC.USEC` is an error frame on the bus; any other `error ...` is a reply.
ServerMessage parse_error(std::span<const std::string_view> args) {
    if (args.size() == 2) {
        const auto error_class = parse_identifier(args[0]);
        const auto stamp = parse_stamp(args[1]);
        if (error_class && stamp) {
            Frame frame;
            frame.id = error_class->id;
            frame.error = true;
            frame.dlc = kMaxDataLength; // SocketCAN's CAN_ERR_DLC; the details are not sent
            return ReceivedFrame{frame, *stamp};
        }
    }
    if (args.empty()) {
        return ErrorReply{};
    }
    // The reason as written, from its first word to its last (the fields view the message).
    const char* begin = args.front().data();
    const char* end = args.back().data() + args.back().size();
    return ErrorReply{std::string(begin, end)};
}

std::string format_id(const Frame& frame) {
    return frame.extended ? fmt::format("{:08X}", frame.id) : fmt::format("{:03X}", frame.id);
}

// The words between a message's brackets (at least one), or why there are none: what both
// sides' parsers start from.
std::variant<std::vector<std::string_view>, Malformed> message_words(std::string_view message) {
    if (message.size() < 2 || message.front() != '<' || message.back() != '>') {
        return Malformed{"a message is enclosed in < and >"};
    }
    auto fields = split_fields(message.substr(1, message.size() - 2));
    if (fields.empty()) {
        return Malformed{"empty message"};
    }
    return fields;
}

} // namespace

Scan scan_message(std::string_view buffer) {
    const std::size_t start = std::min(buffer.find_first_not_of(kWhitespace), buffer.size());
    if (start == buffer.size()) {
        return {Scan::Kind::Incomplete, {}, start};
    }
    if (buffer[start] != '<') {
        return {Scan::Kind::Garbage, {}, 0};
    }
    const std::size_t limit = std::min(buffer.size(), start + kMaxMessageLength);
    for (std::size_t i = start + 1; i < limit; ++i) {
        if (buffer[i] == '>') {
            return {Scan::Kind::Message, buffer.substr(start, i + 1 - start), i + 1};
        }
        if (buffer[i] == '<') {
            return {Scan::Kind::Garbage, {}, 0};
        }
    }
    if (buffer.size() - start >= kMaxMessageLength) {
        return {Scan::Kind::TooLong, {}, 0};
    }
    return {Scan::Kind::Incomplete, {}, start};
}

std::string_view to_string(Mode mode) {
    switch (mode) {
    case Mode::Bcm:
        return "bcm";
    case Mode::Raw:
        return "raw";
    case Mode::Control:
        return "control";
    case Mode::IsoTp:
        return "isotp";
    }
    return "unknown";
}

Command parse_command(std::string_view message) {
    auto words = message_words(message);
    if (const auto* malformed = std::get_if<Malformed>(&words)) {
        return *malformed;
    }
    const auto& fields = std::get<std::vector<std::string_view>>(words);
    const std::string_view name = fields.front();
    const auto args = std::span(fields).subspan(1);
    if (name == "open") {
        if (args.size() != 1 || args[0].size() > kMaxBusNameLength) {
            return Malformed{"open takes one bus name of at most 16 characters"};
        }
        return OpenBus{std::string(args[0])};
    }
    if (const auto mode = mode_named(name)) {
        if (!args.empty()) {
            return Malformed{fmt::format("{} takes no arguments", name)};
        }
        return SwitchMode{*mode};
    }
    if (name == "echo") {
        if (!args.empty()) {
            return Malformed{"echo takes no arguments"};
        }
        return Echo{};
    }
    if (name == "send" || name == "sendrtr") {
        return parse_send(args, name == "sendrtr");
    }
    if (is_unsupported_command(name)) {
        return NotSupported{std::string(name)};
    }
    return Unknown{std::string(name)};
}

Frame frame_for_bus(const Frame& sent) {
    // CiA 301 7.2.8.3.2.1: node guarding on 0x700 + node-ID, node-IDs 1..127.
    constexpr std::uint32_t kFirstGuardId = 0x701;
    constexpr std::uint32_t kLastGuardId = 0x77F;
    const bool guard_request = !sent.remote && !sent.extended && !sent.error && sent.dlc == 0 &&
                               sent.id >= kFirstGuardId && sent.id <= kLastGuardId;
    return guard_request ? Frame::remote_frame(sent.id, 1) : sent;
}

std::string format_send(const Frame& frame) {
    if (frame.remote) {
        return fmt::format("< sendrtr {} {} >", format_id(frame), frame.dlc);
    }
    std::string text = fmt::format("< send {} {} ", format_id(frame), frame.dlc);
    for (const std::uint8_t byte : frame.payload()) {
        text += fmt::format("{:02X} ", byte);
    }
    text += '>';
    return text;
}

std::string format_error(std::string_view reason) {
    std::string text = "< error ";
    for (const char c : reason) {
        const bool printable = c >= ' ' && c <= '~' && c != '<' && c != '>';
        text += printable ? c : '?';
    }
    text += " >";
    return text;
}

std::string format_received(const Frame& frame, core::Duration since_epoch) {
    const std::string stamp = core::format_seconds_micros(core::TimePoint{since_epoch});
    if (frame.error) {
        return fmt::format("< error {:03X} {} >", frame.id, stamp);
    }
    if (frame.remote) {
        return fmt::format("< rtr {} {} {} >", format_id(frame), stamp, frame.dlc);
    }
    std::string text = fmt::format("< frame {} {} ", format_id(frame), stamp);
    for (const std::uint8_t byte : frame.payload()) {
        text += fmt::format("{:02X}", byte);
    }
    text += " >";
    return text;
}

ServerMessage parse_server_message(std::string_view message) {
    auto words = message_words(message);
    if (const auto* malformed = std::get_if<Malformed>(&words)) {
        return *malformed;
    }
    const auto& fields = std::get<std::vector<std::string_view>>(words);
    const std::string_view name = fields.front();
    const auto args = std::span(fields).subspan(1);
    const bool bare = args.empty();
    if (name == "hi" && bare) {
        return Hi{};
    }
    if (name == "ok" && bare) {
        return Ok{};
    }
    if (name == "echo" && bare) {
        return Echo{};
    }
    if (name == "hi" || name == "ok" || name == "echo") {
        return Malformed{fmt::format("{} takes no arguments", name)};
    }
    if (name == "frame") {
        return parse_frame(args);
    }
    if (name == "rtr") {
        return parse_remote(args);
    }
    if (name == "error") {
        return parse_error(args);
    }
    return Unknown{std::string(name)};
}

} // namespace eposp::can::io::socketcand
