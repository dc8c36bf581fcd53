#include "eposp/can/io/socketcand_protocol.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <fmt/format.h>
#include <optional>
#include <span>
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

Command parse_send(std::span<const std::string_view> args, bool remote) {
    if (args.size() < 2) {
        return Malformed{"a send needs an identifier and a length"};
    }
    constexpr std::size_t kExtendedIdDigits = 8;
    const auto id = parse_hex(args[0], kExtendedIdDigits);
    if (!id || *id > kMaxExtendedId) {
        return Malformed{"the identifier must be 1 to 8 hex digits up to 1FFFFFFF"};
    }
    const bool extended = args[0].size() == kExtendedIdDigits || *id > kMaxStandardId;
    if (args[1].size() != 1 || args[1][0] < '0' || args[1][0] > '0' + kMaxDataLength) {
        return Malformed{"the length must be a digit 0 to 8"};
    }
    const auto dlc = static_cast<std::uint8_t>(args[1][0] - '0');
    const auto data_fields = args.subspan(2);
    if (remote) {
        if (!data_fields.empty()) {
            return Malformed{"a sendrtr carries no data bytes"};
        }
        return SendFrame{Frame::remote_frame(*id, dlc, extended)};
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
    return SendFrame{Frame::data_frame(*id, std::span(bytes.data(), dlc), extended)};
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

std::string format_id(const Frame& frame) {
    return frame.extended ? fmt::format("{:08X}", frame.id) : fmt::format("{:03X}", frame.id);
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
    if (message.size() < 2 || message.front() != '<' || message.back() != '>') {
        return Malformed{"a message is enclosed in < and >"};
    }
    const auto fields = split_fields(message.substr(1, message.size() - 2));
    if (fields.empty()) {
        return Malformed{"empty message"};
    }
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

} // namespace eposp::can::io::socketcand
