#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace eposp::vm {

/// The machine-level types an instruction or a native signature can name. IEC types map onto
/// them by representation: BYTE/USINT/CHAR are U8, TIME/LTIME are I64 nanoseconds, a REF_TO or
/// POINTER is Ptr (an address in the VM's memory, 0 is NULL).
enum class Scalar : std::uint8_t { Bool, I8, I16, I32, I64, U8, U16, U32, U64, F32, F64, Ptr };

inline constexpr std::uint8_t kScalarCount = 12;

/// How a BOOL is held in memory: one byte, 0 or 1. A type of its own (not std::uint8_t) so that
/// conversions to BOOL test for non-zero where conversions to USINT truncate.
enum class BoolByte : std::uint8_t {};

constexpr bool is_integer(Scalar s) {
    return s >= Scalar::I8 && s <= Scalar::U64;
}
constexpr bool is_signed_integer(Scalar s) {
    return s >= Scalar::I8 && s <= Scalar::I64;
}

constexpr std::uint32_t scalar_size(Scalar s) {
    switch (s) {
    case Scalar::Bool:
    case Scalar::I8:
    case Scalar::U8:
        return 1;
    case Scalar::I16:
    case Scalar::U16:
        return 2;
    case Scalar::I32:
    case Scalar::U32:
    case Scalar::F32:
        return 4;
    case Scalar::I64:
    case Scalar::U64:
    case Scalar::F64:
    case Scalar::Ptr:
        return 8;
    }
    return 0;
}

std::string_view scalar_name(Scalar s);

/// The integer `bytes` hold (little-endian, as VM memory; at most 8), sign-extended when `s`
/// is signed. A U64 above INT64_MAX comes out negative: callers that compare must check.
std::int64_t integer_value(Scalar s, std::span<const std::uint8_t> bytes);

} // namespace eposp::vm
