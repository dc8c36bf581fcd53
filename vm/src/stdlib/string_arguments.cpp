#include "string_arguments.hpp"

#include "eposp/vm/stdlib/string_layout.hpp"

#include <algorithm>
#include <cstring>

namespace eposp::vm::stdlib {
std::span<std::uint8_t> string_bytes(NativeArgs& args, std::size_t index, CharWidth width) {
    const auto address = args.get<std::uint64_t>(index);
    const auto header = args.memory(address, kStringHeaderSize);
    if (header.empty()) {
        args.fail("STRING pointer is NULL or outside memory");
        return {};
    }
    std::uint16_t capacity;
    std::memcpy(&capacity, header.data(), sizeof capacity);
    const auto bytes = args.memory(address, string_size(capacity, width));
    if (bytes.empty() || !string_capacity(bytes, width)) {
        args.fail(width == CharWidth::Wide ? "pointer does not point to a WSTRING"
                                           : "pointer does not point to a STRING");
        return {};
    }
    return bytes;
}

std::optional<std::string_view> string_parameter(NativeArgs& args, std::size_t index) {
    const auto bytes = string_bytes(args, index, CharWidth::Narrow);
    if (bytes.empty()) {
        return std::nullopt;
    }
    return read_string(bytes);
}

void store_string(NativeArgs& args, std::size_t index, std::string_view text) {
    const auto bytes = string_bytes(args, index, CharWidth::Narrow);
    if (!bytes.empty()) {
        write_string(bytes, text);
    }
}

void TextBuffer::append(std::string_view piece) {
    const auto count = std::min(piece.size(), chars_.size() - size_);
    if (count == 0) {
        return; // an empty view may have a null data(), which memcpy must not get
    }
    std::memcpy(chars_.data() + size_, piece.data(), count);
    size_ += count;
}

} // namespace eposp::vm::stdlib
