#pragma once

// What a native FUNCTION (declared without statements in a linked library, docs/runtime.md
// "Native functions") is handed besides plain scalars: the value an ANY input refers to, the
// elements of an ARRAY[*], and where in the source it is called from.

#include "eposp/vm/native_type.hpp"

#include <cstdint>
#include <cstring>
#include <span>
#include <string>

namespace eposp::vm {

/// The value an ANY input refers to: its type and its bytes in VM memory (for STRING and
/// WSTRING, the whole string: header, characters and terminator).
struct NativeValue {
    NativeType type = NativeType::Bool;
    std::span<const std::uint8_t> bytes;

    bool is_string() const { return type == NativeType::String || type == NativeType::Wstring; }
    /// An elementary value as T (T must be the type's size: `as<std::int16_t>()` for INT).
    template <typename T>
    T as() const;
    /// A STRING's text, a WSTRING's as UTF-8; empty for any other type.
    std::string text() const;
};

/// An ARRAY[*] argument (one dimension): its element type and size, bounds and elements.
struct NativeArray {
    NativeType element = NativeType::Bool;
    std::uint32_t element_size = 0;
    std::int32_t lower = 0;
    std::uint32_t count = 0;
    std::span<std::uint8_t> bytes; ///< count * element_size bytes

    std::int64_t upper() const { return std::int64_t{lower} + count - 1; }
    /// The element at 0-based `i` (< count).
    NativeValue at(std::uint32_t i) const {
        return {element, bytes.subspan(std::size_t{i} * element_size, element_size)};
    }
};

/// Where a native call is in the source: the POU and line run-time errors would name (inside
/// a call copied in place, the copied callee and its line).
struct NativeCallSite {
    std::string pou;
    std::uint32_t line = 0; ///< 0 when the POU has no line table
};

template <typename T>
T NativeValue::as() const {
    T value{};
    if (bytes.size() == sizeof(T)) {
        std::memcpy(&value, bytes.data(), sizeof(T));
    }
    return value;
}

} // namespace eposp::vm
