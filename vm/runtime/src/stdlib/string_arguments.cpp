#include "string_arguments.hpp"

#include "eposp/vm/stdlib/string_layout.hpp"

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

template <>
StringParameter<char>::StringParameter(NativeArgs& args, std::size_t index) {
    const auto text = string_parameter(args, index);
    valid_ = text.has_value();
    text_ = text.value_or(std::string_view{});
}

template <>
StringParameter<char16_t>::StringParameter(NativeArgs& args, std::size_t index) {
    const auto bytes = string_bytes(args, index, CharWidth::Wide);
    valid_ = !bytes.empty();
    for (std::size_t i = 0; valid_ && i < string_length(bytes); ++i) {
        const char16_t unit = wstring_unit(bytes, i);
        text_.append({&unit, 1});
    }
}

template <>
void store_text<char>(NativeArgs& args, std::size_t index, std::string_view text) {
    store_string(args, index, text);
}

template <>
void store_text<char16_t>(NativeArgs& args, std::size_t index, std::u16string_view text) {
    const auto bytes = string_bytes(args, index, CharWidth::Wide);
    if (!bytes.empty()) {
        write_wstring(bytes, text);
    }
}

} // namespace eposp::vm::stdlib
