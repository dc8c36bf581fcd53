#pragma once

// IEC 61131-3 keywords and identifiers are ASCII and ignore its case (ed. 3, 6.1.2), whatever
// the locale: one comparison for the parser, the literal decoder and the name maps.

#include <cstddef>
#include <string_view>

namespace eposp::compiler {

/// `c` in upper case if it is an ASCII letter.
constexpr char upper_ascii(char c) {
    return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}

constexpr bool equal_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (upper_ascii(a[i]) != upper_ascii(b[i])) {
            return false;
        }
    }
    return true;
}

} // namespace eposp::compiler
