#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>

namespace eposp::compiler::sema {

/// `c` in upper case if it is an ASCII letter: IEC identifiers are ASCII and ignore its case
/// (6.1.2), whatever the locale.
constexpr char upper_ascii(char c) {
    return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}

/// Hash and equality that ignore ASCII case, so that a name is looked up as it is written,
/// without building its folded copy first.
struct NameHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view name) const noexcept {
        std::size_t hash = 14695981039346656037ULL; // FNV-1a
        for (const char c : name) {
            hash = (hash ^ static_cast<unsigned char>(upper_ascii(c))) * 1099511628211ULL;
        }
        return hash;
    }
};

struct NameEqual {
    using is_transparent = void;
    bool operator()(std::string_view a, std::string_view b) const noexcept {
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
};

/// A map from IEC names, compared case-insensitively, to `Value`; keys keep their spelling.
template <typename Value>
using NameMap = std::unordered_map<std::string, Value, NameHash, NameEqual>;

} // namespace eposp::compiler::sema
