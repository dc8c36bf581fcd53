#include "eposp/vm/native_type.hpp"

#include <array>

namespace eposp::vm {
namespace {

constexpr std::array<std::string_view, kNativeTypeCount> kTypeNames = {
    "BOOL",          "SINT",  "INT",    "DINT",    "LINT",  "USINT",       "UINT",
    "UDINT",         "ULINT", "BYTE",   "WORD",    "DWORD", "LWORD",       "REAL",
    "LREAL",         "TIME",  "LTIME",  "DATE",    "LDATE", "TIME_OF_DAY", "LTOD",
    "DATE_AND_TIME", "LDT",   "STRING", "WSTRING", "CHAR",  "WCHAR"};

} // namespace

std::string_view native_type_name(NativeType type) {
    const auto index = static_cast<std::size_t>(type);
    return index < kTypeNames.size() ? kTypeNames[index] : "?";
}

Scalar native_scalar(NativeType type) {
    using S = Scalar;
    switch (type) {
    case NativeType::Bool:
        return S::Bool;
    case NativeType::Sint:
        return S::I8;
    case NativeType::Int:
        return S::I16;
    case NativeType::Dint:
        return S::I32;
    case NativeType::Usint:
    case NativeType::Byte:
    case NativeType::Char:
        return S::U8;
    case NativeType::Uint:
    case NativeType::Word:
    case NativeType::Wchar:
        return S::U16;
    case NativeType::Udint:
    case NativeType::Dword:
        return S::U32;
    case NativeType::Ulint:
    case NativeType::Lword:
        return S::U64;
    case NativeType::Real:
        return S::F32;
    case NativeType::Lreal:
        return S::F64;
    case NativeType::String:
    case NativeType::Wstring:
        return S::Ptr;
    default: // LINT, the durations, dates and times of day: 64-bit counts
        return S::I64;
    }
}

} // namespace eposp::vm
