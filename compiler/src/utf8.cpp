#include "utf8.hpp"

namespace eposp::compiler::utf8 {

std::optional<char32_t> decode(std::string_view text, std::size_t& position) {
    const auto byte = [&](std::size_t i) {
        return static_cast<unsigned char>(text[i]);
    };
    const unsigned char lead = byte(position);
    std::size_t length = 0;
    char32_t code_point = 0;
    if (lead < 0x80) {
        ++position;
        return lead;
    }
    if ((lead & 0xE0) == 0xC0) {
        length = 2;
        code_point = lead & 0x1Fu;
    } else if ((lead & 0xF0) == 0xE0) {
        length = 3;
        code_point = lead & 0x0Fu;
    } else if ((lead & 0xF8) == 0xF0) {
        length = 4;
        code_point = lead & 0x07u;
    } else {
        ++position;
        return std::nullopt;
    }
    if (position + length > text.size()) {
        ++position;
        return std::nullopt;
    }
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(position + i) & 0xC0) != 0x80) {
            ++position;
            return std::nullopt;
        }
        code_point = (code_point << 6) | (byte(position + i) & 0x3Fu);
    }
    // Overlong forms, surrogates and values past U+10FFFF are not valid UTF-8.
    static constexpr char32_t kSmallestOf[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code_point < kSmallestOf[length] || code_point > 0x10FFFF ||
        (code_point >= 0xD800 && code_point <= 0xDFFF)) {
        ++position;
        return std::nullopt;
    }
    position += length;
    return code_point;
}

std::string from_windows_1252(std::string_view text) {
    // 0x80..0x9F, where Windows-1252 differs from Latin-1 (unassigned bytes map to themselves).
    static constexpr char16_t kHigh[32] = {
        0x20AC, 0x0081, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
        0x2039, 0x0152, 0x008D, 0x017D, 0x008F, 0x0090, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
        0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0x009D, 0x017E, 0x0178};
    std::string result;
    result.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        const char32_t code_point = byte >= 0x80 && byte < 0xA0 ? kHigh[byte - 0x80] : byte;
        if (code_point < 0x80) {
            result += static_cast<char>(code_point);
        } else if (code_point < 0x800) {
            result += static_cast<char>(0xC0 | (code_point >> 6));
            result += static_cast<char>(0x80 | (code_point & 0x3F));
        } else {
            result += static_cast<char>(0xE0 | (code_point >> 12));
            result += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
            result += static_cast<char>(0x80 | (code_point & 0x3F));
        }
    }
    return result;
}

std::size_t offset_of_column(std::string_view line, std::uint32_t column) {
    std::size_t position = 0;
    for (std::uint32_t current = 1; current < column && position < line.size(); ++current) {
        decode(line, position);
    }
    return position;
}

} // namespace eposp::compiler::utf8
