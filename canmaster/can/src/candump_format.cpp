#include "eposp/can/candump_format.hpp"

#include "socketcan_id.hpp"

#include <charconv>
#include <chrono>
#include <cstdint>
#include <fmt/format.h>
#include <iterator>
#include <limits>
#include <vector>

namespace eposp::can {
namespace {

constexpr std::size_t kStandardIdDigits = 3;
constexpr std::size_t kExtendedIdDigits = 8;
constexpr std::size_t kMicrosecondDigits = 6;
// The last whole second a TraceTime (signed 64-bit nanoseconds) can hold.
constexpr std::uint64_t kMaxSeconds = std::numeric_limits<std::int64_t>::max() / 1'000'000'000 - 1;

core::Error error(std::string message) {
    return core::Error{std::move(message)};
}

// Names a character in a message without echoing control bytes of untrusted input.
std::string describe(char c) {
    const auto code = static_cast<unsigned char>(c);
    if (code >= 0x20 && code < 0x7F) {
        return fmt::format("'{}'", c);
    }
    return fmt::format("byte 0x{:02X}", code);
}

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// Reads all of `digits` as an unsigned number of at most 32 bits in `base`.
core::Result<std::uint32_t> parse_number(std::string_view digits, int base, std::string_view what) {
    if (digits.empty()) {
        return error(fmt::format("missing {}", what));
    }
    std::uint32_t value = 0;
    const char* end = digits.data() + digits.size();
    const auto [stop, status] = std::from_chars(digits.data(), end, value, base);
    if (stop != end) {
        return error(fmt::format("invalid {} digit {} in {}", base == 16 ? "hex" : "decimal",
                                 describe(*stop), what));
    }
    if (status != std::errc{}) {
        return error(fmt::format("{} is out of range", what));
    }
    return value;
}

struct Identifier {
    std::uint32_t id = 0;
    bool extended = false;
    bool error = false;
};

// can-utils tells the formats apart by length: 3 digits standard, 8 digits extended or error.
core::Result<Identifier> parse_identifier(std::string_view digits) {
    if (digits.size() != kStandardIdDigits && digits.size() != kExtendedIdDigits) {
        return error(fmt::format("identifier must have 3 (standard) or 8 (extended) hex digits, "
                                 "not {}",
                                 digits.size()));
    }
    auto value = parse_number(digits, 16, "identifier");
    if (!value) {
        return core::Error{value.error()};
    }
    if (digits.size() == kStandardIdDigits) {
        if (*value > kMaxStandardId) {
            return error(fmt::format("standard identifier 0x{:03X} is above 0x7FF", *value));
        }
        return Identifier{*value, false, false};
    }
    if ((*value & socketcan::kErrorFlag) != 0) {
        if ((*value & (socketcan::kExtendedFlag | socketcan::kRemoteFlag)) != 0) {
            return error(
                fmt::format("error frame identifier 0x{:08X} has EFF/RTR flags set", *value));
        }
        return Identifier{*value & socketcan::kIdMask, false, true};
    }
    if (*value > kMaxExtendedId) {
        return error(fmt::format("extended identifier 0x{:08X} is above 0x1FFFFFFF", *value));
    }
    return Identifier{*value, true, false};
}

// `R` followed by nothing (DLC 0) or one DLC digit, as can-utils writes remote frames.
core::Result<std::uint8_t> parse_remote_dlc(std::string_view text) {
    if (text.empty()) {
        return std::uint8_t{0};
    }
    if (text.size() > 1 || text[0] < '0' || text[0] > '8') {
        return error("a remote frame's 'R' may only be followed by one DLC digit 0..8");
    }
    return static_cast<std::uint8_t>(text[0] - '0');
}

// Pairs of hex digits, optionally separated by '.'.
core::Result<Frame> parse_data(std::string_view text, Frame frame) {
    frame.dlc = 0;
    while (!text.empty()) {
        if (text[0] == '.') {
            text.remove_prefix(1);
            continue;
        }
        if (frame.dlc == kMaxDataLength) {
            return error("more than 8 data bytes");
        }
        if (text.size() < 2 || text[1] == '.') {
            return error(fmt::format("data byte {} has only one hex digit", frame.dlc + 1));
        }
        const auto byte =
            parse_number(text.substr(0, 2), 16, fmt::format("data byte {}", frame.dlc + 1));
        if (!byte) {
            return core::Error{byte.error()};
        }
        frame.data[frame.dlc++] = static_cast<std::uint8_t>(*byte);
        text.remove_prefix(2);
    }
    return frame;
}

// `seconds.microseconds`, the microseconds always 6 digits as candump writes them.
core::Result<TraceTime> parse_timestamp(std::string_view text) {
    const auto dot = text.find('.');
    if (dot == std::string_view::npos) {
        return error("timestamp must be seconds.microseconds");
    }
    const std::string_view second_digits = text.substr(0, dot);
    const std::string_view micro_digits = text.substr(dot + 1);
    std::uint64_t seconds = 0;
    const char* end = second_digits.data() + second_digits.size();
    const auto [stop, status] = std::from_chars(second_digits.data(), end, seconds);
    if (second_digits.empty() || stop != end || status == std::errc::invalid_argument) {
        return error("timestamp seconds must be decimal digits");
    }
    if (status == std::errc::result_out_of_range || seconds > kMaxSeconds) {
        return error("timestamp seconds are out of range");
    }
    if (micro_digits.size() != kMicrosecondDigits) {
        return error("timestamp must have 6 digits of microseconds after the '.'");
    }
    const auto micros = parse_number(micro_digits, 10, "timestamp microseconds");
    if (!micros) {
        return core::Error{micros.error()};
    }
    return TraceTime(std::chrono::seconds(static_cast<std::int64_t>(seconds)) +
                     std::chrono::microseconds(*micros));
}

std::vector<std::string_view> split_fields(std::string_view text) {
    std::vector<std::string_view> fields;
    std::size_t pos = 0;
    while (pos < text.size()) {
        if (is_blank(text[pos])) {
            ++pos;
            continue;
        }
        std::size_t end = pos;
        while (end < text.size() && !is_blank(text[end])) {
            ++end;
        }
        fields.push_back(text.substr(pos, end - pos));
        pos = end;
    }
    return fields;
}

bool is_direction(std::string_view field) {
    return field == "R" || field == "T";
}

} // namespace

std::string format_candump_frame(const Frame& frame) {
    std::string text;
    auto out = std::back_inserter(text);
    if (frame.error) {
        fmt::format_to(out, "{:08X}#", socketcan::kErrorFlag | (frame.id & socketcan::kIdMask));
    } else if (frame.extended) {
        fmt::format_to(out, "{:08X}#", frame.id);
    } else {
        fmt::format_to(out, "{:03X}#", frame.id);
    }
    if (frame.remote && !frame.error) {
        text += 'R';
        if (frame.dlc != 0) {
            fmt::format_to(out, "{:X}", frame.dlc);
        }
        return text;
    }
    for (const std::uint8_t byte : frame.payload()) {
        fmt::format_to(out, "{:02X}", byte);
    }
    return text;
}

core::Result<Frame> parse_candump_frame(std::string_view text) {
    const auto hash = text.find('#');
    if (hash == std::string_view::npos) {
        return error("missing '#' between identifier and data");
    }
    const auto identifier = parse_identifier(text.substr(0, hash));
    if (!identifier) {
        return core::Error{identifier.error()};
    }
    Frame frame;
    frame.id = identifier->id;
    frame.extended = identifier->extended;
    frame.error = identifier->error;

    const std::string_view body = text.substr(hash + 1);
    if (body.starts_with('#')) {
        return error("CAN FD frames ('##') are not supported");
    }
    if (body.starts_with('R')) {
        if (frame.error) {
            return error("an error frame cannot be a remote frame");
        }
        const auto dlc = parse_remote_dlc(body.substr(1));
        if (!dlc) {
            return core::Error{dlc.error()};
        }
        frame.remote = true;
        frame.dlc = *dlc;
        return frame;
    }
    return parse_data(body, frame);
}

std::string format_candump_line(const CandumpRecord& record) {
    const auto since_epoch = record.time.time_since_epoch();
    const auto seconds = std::chrono::floor<std::chrono::seconds>(since_epoch);
    const auto micros = std::chrono::floor<std::chrono::microseconds>(since_epoch - seconds);
    return fmt::format("({:010}.{:06}) {} {}", seconds.count(), micros.count(),
                       record.interface_name, format_candump_frame(record.frame));
}

core::Result<CandumpRecord> parse_candump_line(std::string_view line) {
    if (!line.starts_with('(')) {
        return error("a log line must start with '(' and a timestamp");
    }
    const auto close = line.find(')');
    if (close == std::string_view::npos) {
        return error("missing ')' after the timestamp");
    }
    auto time = parse_timestamp(line.substr(1, close - 1));
    if (!time) {
        return core::Error{time.error()};
    }
    const auto fields = split_fields(line.substr(close + 1));
    if (fields.empty()) {
        return error("missing interface name after the timestamp");
    }
    if (fields.size() == 1) {
        return error("missing frame after the interface name");
    }
    if (fields.size() > 3 || (fields.size() == 3 && !is_direction(fields[2]))) {
        return error("unexpected text after the frame");
    }
    auto frame = parse_candump_frame(fields[1]);
    if (!frame) {
        return core::Error{frame.error()};
    }
    return CandumpRecord{*time, std::string(fields[0]), *frame};
}

} // namespace eposp::can
