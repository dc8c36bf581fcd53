#include "st_types.hpp"

namespace eposp::differential {
namespace {

constexpr std::array<const char*, 16> kNames = {"BOOL",  "SINT",  "INT",   "DINT",  "LINT", "USINT",
                                                "UINT",  "UDINT", "ULINT", "BYTE",  "WORD", "DWORD",
                                                "LWORD", "REAL",  "LREAL", "STRING"};

} // namespace

std::string type_name(Ty type) {
    return kNames[static_cast<std::size_t>(type)];
}

int bits_of(Ty type) {
    switch (type) {
    case Ty::Sint:
    case Ty::Usint:
    case Ty::Byte:
        return 8;
    case Ty::Int:
    case Ty::Uint:
    case Ty::Word:
        return 16;
    case Ty::Dint:
    case Ty::Udint:
    case Ty::Dword:
    case Ty::Real:
        return 32;
    case Ty::Bool:
        return 1;
    default:
        return 64;
    }
}

std::string min_text(Ty type) {
    if (!is_signed(type)) {
        return "0";
    }
    switch (bits_of(type)) {
    case 8:
        return "-128";
    case 16:
        return "-32768";
    case 32:
        return "-2147483648";
    default:
        return "-9223372036854775808";
    }
}

std::string max_text(Ty type) {
    const bool sign = is_signed(type);
    switch (bits_of(type)) {
    case 8:
        return sign ? "127" : "255";
    case 16:
        return sign ? "32767" : "65535";
    case 32:
        return sign ? "2147483647" : "4294967295";
    default:
        return sign ? "9223372036854775807" : "18446744073709551615";
    }
}

std::string one_literal(Ty type) {
    switch (type) {
    case Ty::Bool:
        return "FALSE";
    case Ty::Real:
    case Ty::Lreal:
        return type_name(type) + "#1.0";
    case Ty::String:
        return "'a'";
    default:
        return type_name(type) + "#1";
    }
}

} // namespace eposp::differential
