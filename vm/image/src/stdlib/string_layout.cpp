#include "eposp/vm/stdlib/string_layout.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace eposp::vm::stdlib {
namespace {

void put_u16(std::uint8_t* at, std::uint16_t value) {
    std::memcpy(at, &value, sizeof value);
}

std::uint16_t get_u16(const std::uint8_t* at) {
    std::uint16_t value;
    std::memcpy(&value, at, sizeof value);
    return value;
}

void check_capacity(std::uint32_t capacity) {
    if (capacity == 0 || capacity > kMaxStringCapacity) {
        throw std::logic_error("string capacity outside 1..32767");
    }
}

} // namespace

std::vector<std::uint8_t> string_image(std::uint32_t capacity, std::string_view text) {
    check_capacity(capacity);
    std::vector<std::uint8_t> bytes(string_size(capacity), 0);
    put_u16(bytes.data(), static_cast<std::uint16_t>(capacity));
    write_string(bytes, text);
    return bytes;
}

std::vector<std::uint8_t> wstring_image(std::uint32_t capacity, std::u16string_view text) {
    check_capacity(capacity);
    std::vector<std::uint8_t> bytes(string_size(capacity, CharWidth::Wide), 0);
    put_u16(bytes.data(), static_cast<std::uint16_t>(capacity));
    write_wstring(bytes, text);
    return bytes;
}

std::optional<std::uint16_t> string_capacity(std::span<const std::uint8_t> bytes, CharWidth width) {
    if (bytes.size() < kStringHeaderSize) {
        return std::nullopt;
    }
    const auto capacity = get_u16(bytes.data());
    const auto length = get_u16(bytes.data() + 2);
    if (capacity == 0 || capacity > kMaxStringCapacity || length > capacity ||
        bytes.size() < string_size(capacity, width)) {
        return std::nullopt;
    }
    return capacity;
}

std::optional<std::string_view> read_string(std::span<const std::uint8_t> bytes) {
    if (!string_capacity(bytes)) {
        return std::nullopt;
    }
    return std::string_view(reinterpret_cast<const char*>(bytes.data() + kStringHeaderSize),
                            get_u16(bytes.data() + 2));
}

std::uint16_t write_string(std::span<std::uint8_t> bytes, std::string_view text) {
    const auto capacity = get_u16(bytes.data());
    const auto length = static_cast<std::uint16_t>(std::min<std::size_t>(text.size(), capacity));
    if (length != 0) { // an empty view may have no data() at all
        std::memmove(bytes.data() + kStringHeaderSize, text.data(), length);
    }
    bytes[kStringHeaderSize + length] = 0;
    put_u16(bytes.data() + 2, length);
    return length;
}

std::uint16_t write_wstring(std::span<std::uint8_t> bytes, std::u16string_view text) {
    const auto capacity = get_u16(bytes.data());
    const auto length = static_cast<std::uint16_t>(std::min<std::size_t>(text.size(), capacity));
    if (length != 0) { // an empty view may have no data() at all
        std::memcpy(bytes.data() + kStringHeaderSize, text.data(), length * sizeof(char16_t));
    }
    put_u16(bytes.data() + kStringHeaderSize + 2 * length, 0);
    put_u16(bytes.data() + 2, length);
    return length;
}

std::uint16_t string_length(std::span<const std::uint8_t> bytes) {
    return get_u16(bytes.data() + 2);
}

char16_t wstring_unit(std::span<const std::uint8_t> bytes, std::size_t i) {
    return static_cast<char16_t>(get_u16(bytes.data() + kStringHeaderSize + 2 * i));
}

} // namespace eposp::vm::stdlib
