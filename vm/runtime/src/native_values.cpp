// The pointer arguments of native functions (native_values.hpp): STRING and WSTRING
// parameters, ANY inputs and ARRAY[*] references, each checked against VM memory and the
// string layout before a host reads it.

#include "eposp/vm/native.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"

namespace eposp::vm {
namespace {

using stdlib::CharWidth;

void append_utf8(std::string& out, char32_t code) {
    if (code < 0x80) {
        out += static_cast<char>(code);
    } else if (code < 0x800) {
        out += static_cast<char>(0xC0 | (code >> 6));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
        out += static_cast<char>(0xE0 | (code >> 12));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (code >> 18));
        out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    }
}

/// The WSTRING whose consistent header starts `bytes`, as UTF-8 (an unpaired surrogate
/// becomes U+FFFD).
std::string wide_to_utf8(std::span<const std::uint8_t> bytes) {
    std::string out;
    const std::size_t length = stdlib::string_length(bytes);
    for (std::size_t i = 0; i < length; ++i) {
        const char16_t unit = stdlib::wstring_unit(bytes, i);
        if (unit >= 0xD800 && unit < 0xDC00 && i + 1 < length) {
            const char16_t low = stdlib::wstring_unit(bytes, i + 1);
            if (low >= 0xDC00 && low < 0xE000) {
                append_utf8(out, 0x10000 + ((char32_t{unit} - 0xD800) << 10) + (low - 0xDC00));
                ++i;
                continue;
            }
        }
        append_utf8(out, unit >= 0xD800 && unit < 0xE000 ? char32_t{0xFFFD} : char32_t{unit});
    }
    return out;
}

/// The string at `address`, whole, if its header is consistent; else empty.
std::span<std::uint8_t> string_at(const NativeArgs& args, std::uint64_t address, CharWidth width) {
    const auto header = args.memory(address, stdlib::kStringHeaderSize);
    if (header.empty()) {
        return {};
    }
    const auto capacity = static_cast<std::uint32_t>(header[0] | header[1] << 8);
    const auto bytes = args.memory(address, stdlib::string_size(capacity, width));
    return !bytes.empty() && stdlib::string_capacity(bytes, width) ? bytes
                                                                   : std::span<std::uint8_t>{};
}

} // namespace

std::string NativeValue::text() const {
    if (type == NativeType::String) {
        return std::string(stdlib::read_string(bytes).value_or(std::string_view{}));
    }
    if (type == NativeType::Wstring && stdlib::string_capacity(bytes, CharWidth::Wide)) {
        return wide_to_utf8(bytes);
    }
    return {};
}

std::string NativeArgs::text(std::size_t index) {
    const auto bytes = string_at(*this, get<std::uint64_t>(index), CharWidth::Narrow);
    if (bytes.empty()) {
        fail("pointer does not point to a STRING");
        return {};
    }
    return std::string(stdlib::read_string(bytes).value_or(std::string_view{}));
}

std::string NativeArgs::wide_text(std::size_t index) {
    const auto bytes = string_at(*this, get<std::uint64_t>(index), CharWidth::Wide);
    if (bytes.empty()) {
        fail("pointer does not point to a WSTRING");
        return {};
    }
    return wide_to_utf8(bytes);
}

NativeValue NativeArgs::any(std::size_t index) {
    const auto address = get<std::uint64_t>(index);
    const auto descriptor = get<std::uint32_t>(index + 1);
    const NativeType type = descriptor_type(descriptor);
    std::span<std::uint8_t> bytes;
    if (type == NativeType::String || type == NativeType::Wstring) {
        bytes = string_at(*this, address,
                          type == NativeType::Wstring ? CharWidth::Wide : CharWidth::Narrow);
    } else if (static_cast<std::size_t>(type) < kNativeTypeCount) {
        bytes = memory(address, descriptor_bytes(descriptor));
    }
    if (bytes.empty()) {
        fail("an ANY argument does not point to a value of its type");
        return {};
    }
    return {type, bytes};
}

NativeArray NativeArgs::array(std::size_t index) {
    // The reference of an ARRAY[*]: the address, then the lower bound and count (compiler's
    // sema::kConformantBoundsOffset).
    const auto reference = memory(get<std::uint64_t>(index), 16);
    const auto descriptor = get<std::uint32_t>(index + 1);
    NativeArray array;
    if (!reference.empty()) {
        std::uint64_t address;
        std::memcpy(&address, reference.data(), sizeof address);
        std::memcpy(&array.lower, reference.data() + 8, sizeof array.lower);
        std::memcpy(&array.count, reference.data() + 12, sizeof array.count);
        array.element = descriptor_type(descriptor);
        array.element_size = descriptor_bytes(descriptor);
        const std::uint64_t size = std::uint64_t{array.count} * array.element_size;
        if (size <= UINT32_MAX) {
            array.bytes = memory(address, static_cast<std::uint32_t>(size));
        }
    }
    if (array.bytes.empty() && (reference.empty() || array.count != 0)) {
        fail("an ARRAY[*] argument does not point to an array");
        return {};
    }
    return array;
}

} // namespace eposp::vm
