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

std::size_t offset_of_column(std::string_view line, std::uint32_t column) {
    std::size_t position = 0;
    for (std::uint32_t current = 1; current < column && position < line.size(); ++current) {
        decode(line, position);
    }
    return position;
}

} // namespace eposp::compiler::utf8
