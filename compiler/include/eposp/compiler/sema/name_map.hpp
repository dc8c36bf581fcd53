#pragma once

#include "eposp/compiler/ascii_case.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>

namespace eposp::compiler::sema {

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
        return equal_ignoring_case(a, b);
    }
};

/// A map from IEC names, compared case-insensitively, to `Value`; keys keep their spelling.
template <typename Value>
using NameMap = std::unordered_map<std::string, Value, NameHash, NameEqual>;

} // namespace eposp::compiler::sema
