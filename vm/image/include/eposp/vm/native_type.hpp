#pragma once

// How a native FUNCTION (docs/runtime.md "Native functions") is told the type of an ANY input or
// of the elements of an ARRAY[*]: a U32 descriptor after the pointer in its argument block, which
// the compiler writes and the runtime reads (native_values.hpp).

#include "eposp/vm/scalar.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

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
inline constexpr std::size_t kNativeTypeCount = static_cast<std::size_t>(NativeType::Wchar) + 1;

/// The name of `type` as IEC 61131-3 spells it (`TIME_OF_DAY`).
std::string_view native_type_name(NativeType type);
/// The scalar a value of `type` is held in: how an opcode, a native and the compiler take it
/// (the times and dates are 64-bit nanosecond counts, a text is passed by address).
Scalar native_scalar(NativeType type);

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

} // namespace eposp::vm
