#pragma once

// The FUNCTIONs every generated program folds its values with: Mix (a ULINT), MixR (an LREAL,
// by its integer part and fraction) and MixS (a STRING, by its length and characters).

#include <string>
#include <vector>

namespace eposp::differential {

/// The characters generated strings are made of; MixS folds each by its position here.
inline constexpr const char* kStringAlphabet =
    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-";

/// The ST source of Mix, MixR and MixS, one FUNCTION each.
std::vector<std::string> checksum_functions();

} // namespace eposp::differential
