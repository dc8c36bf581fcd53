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

} // namespace eposp::vm
