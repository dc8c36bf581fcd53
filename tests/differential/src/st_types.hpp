#pragma once

// The elementary types the generator uses, with what it needs to know of each.

#include <array>
#include <cstdint>
#include <string>

namespace eposp::differential {

enum class Ty : std::uint8_t {
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
    String,
};

inline constexpr std::array<Ty, 12> kIntegerTypes = {Ty::Sint,  Ty::Int,  Ty::Dint,  Ty::Lint,
                                                     Ty::Usint, Ty::Uint, Ty::Udint, Ty::Ulint,
                                                     Ty::Byte,  Ty::Word, Ty::Dword, Ty::Lword};

std::string type_name(Ty type);
/// The width in bits of an integer type.
int bits_of(Ty type);
inline bool is_signed(Ty type) {
    return type >= Ty::Sint && type <= Ty::Lint;
}
inline bool is_unsigned(Ty type) {
    return type >= Ty::Usint && type <= Ty::Ulint;
}
inline bool is_bit_string(Ty type) {
    return type >= Ty::Byte && type <= Ty::Lword;
}
inline bool is_integer(Ty type) {
    return type >= Ty::Sint && type <= Ty::Lword;
}
inline bool is_real(Ty type) {
    return type == Ty::Real || type == Ty::Lreal;
}
/// SINT, INT, USINT and UINT are computed in DINT inside an expression (st-language.md), BYTE and
/// WORD perhaps too: these must keep their in-expression values small.
inline bool is_narrow(Ty type) {
    return is_integer(type) && bits_of(type) < 32;
}

/// The smallest and largest value of an integer type, as text.
std::string min_text(Ty type);
std::string max_text(Ty type);

/// A literal of the type whose value is one (FALSE, '' ... for the others): the reducer's
/// replacement for an expression.
std::string one_literal(Ty type);

} // namespace eposp::differential
