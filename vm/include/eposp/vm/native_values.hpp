#pragma once

// What a native FUNCTION (declared without statements in a linked library, docs/runtime.md
// "Native functions") is handed besides plain scalars: the value an ANY input refers to, the
// elements of an ARRAY[*], and where in the source it is called from.

#include <cstdint>
#include <cstring>
#include <span>
#include <string>

namespace eposp::vm {

/// The type of a value passed to an ANY input or held by an ARRAY[*] argument, in the order of
/// IEC 61131-3 ed. 3 table 10 as the compiler lists it. An enumeration arrives as its base
/// integer type; a subrange as its base type.
enum class NativeType : std::uint8_t {
    Bool,
    Sint,
    Int,
    Dint,
    Lint,
    Usint,
    Uint,
    Udint,
    Ulint,
    Byte,
    Word,
    Dword,
    Lword,
    Real,
    Lreal,
    Time,
    Ltime,
    Date,
    Ldate,
    TimeOfDay,
    Ltod,
    DateAndTime,
    Ldt,
    String,
    Wstring,
    Char,
    Wchar,
};

/// The name of `type` as IEC 61131-3 spells it (`TIME_OF_DAY`).
std::string_view native_type_name(NativeType type);

/// The U32 descriptor that follows the pointer of an ANY or ARRAY[*] argument: the type in the
/// low byte, the size in bytes of the value (of one element) above it.
constexpr std::uint32_t native_descriptor(NativeType type, std::uint32_t bytes) {
    return static_cast<std::uint32_t>(type) | bytes << 8;
}
constexpr NativeType descriptor_type(std::uint32_t descriptor) {
    return static_cast<NativeType>(descriptor & 0xFF);
}
constexpr std::uint32_t descriptor_bytes(std::uint32_t descriptor) {
    return descriptor >> 8;
}

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
