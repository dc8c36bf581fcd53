// IEC 61131-3 (3rd ed.) 6.6.2.5.12, table 43: the character string functions. Positions are
// 1-based. Where the standard leaves out-of-range arguments open, the result is the part of the
// request that exists (CODESYS behaves so for LEFT/RIGHT/MID): lengths below 0 count as 0,
// lengths past the end are cut, and a position outside the string selects nothing (MID, DELETE,
// REPLACE) or is clamped to the nearest end (INSERT).

#include "library_parts.hpp"
#include "string_arguments.hpp"

#include <algorithm>
#include <compare>

namespace eposp::vm::stdlib {
namespace {

using S = Scalar;

/// `count` clamped to 0..limit.
std::size_t clamp_count(std::int32_t count, std::size_t limit) {
    return count <= 0 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(count), limit);
}

/// The 0-based index of 1-based position `position` if it names a character of `text`.
std::optional<std::size_t> index_of(std::string_view text, std::int32_t position) {
    if (position < 1 || static_cast<std::size_t>(position) > text.size()) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(position - 1);
}

std::string_view mid(std::string_view text, std::int32_t length, std::int32_t position) {
    const auto start = index_of(text, position);
    return start ? text.substr(*start, clamp_count(length, text.size() - *start))
                 : std::string_view{};
}

/// `text` with `length` characters from `position` replaced by `insert`.
void splice(TextBuffer& out, std::string_view text, std::int32_t length, std::int32_t position,
            std::string_view insert) {
    const auto start = index_of(text, position);
    if (!start) {
        out.append(text);
        return;
    }
    out.append(text.substr(0, *start));
    out.append(insert);
    out.append(text.substr(*start + clamp_count(length, text.size() - *start)));
}

std::int32_t find(std::string_view haystack, std::string_view needle) {
    if (needle.empty()) {
        return 0;
    }
    const auto at = haystack.find(needle);
    return at == std::string_view::npos ? 0 : static_cast<std::int32_t>(at + 1);
}

// Byte-wise lexicographic order (characters as unsigned codes), as CODESYS compares.
std::strong_ordering compare(std::string_view a, std::string_view b) {
    return a.compare(b) <=> 0;
}

void add_comparison(NativeRegistry& registry, const char* name,
                    bool (*holds)(std::strong_ordering)) {
    registry.add(name, {true, S::Bool, {S::Ptr, S::Ptr}}, [holds](NativeArgs& args) {
        const auto a = string_parameter(args, 0);
        const auto b = a ? string_parameter(args, 1) : std::nullopt;
        if (b) {
            args.set_result(static_cast<std::uint8_t>(holds(compare(*a, *b))));
        }
    });
}

} // namespace

void register_string_functions(NativeRegistry& registry) {
    registry.add("LEN", {true, S::I32, {S::Ptr}}, [](NativeArgs& args) {
        if (const auto text = string_parameter(args, 0)) {
            args.set_result(static_cast<std::int32_t>(text->size()));
        }
    });
    // ASSIGN_STRING(dst, src): `dst := src` between STRINGs of different capacities.
    registry.add("ASSIGN_STRING", {false, S::Bool, {S::Ptr, S::Ptr}}, [](NativeArgs& args) {
        if (const auto text = string_parameter(args, 1)) {
            store_string(args, 0, *text);
        }
    });
    registry.add("LEFT", {false, S::Bool, {S::Ptr, S::Ptr, S::I32}}, [](NativeArgs& args) {
        if (const auto text = string_parameter(args, 1)) {
            store_string(args, 0,
                         text->substr(0, clamp_count(args.get<std::int32_t>(2), text->size())));
        }
    });
    registry.add("RIGHT", {false, S::Bool, {S::Ptr, S::Ptr, S::I32}}, [](NativeArgs& args) {
        if (const auto text = string_parameter(args, 1)) {
            const auto count = clamp_count(args.get<std::int32_t>(2), text->size());
            store_string(args, 0, text->substr(text->size() - count));
        }
    });
    // MID(IN, L, P)
    registry.add("MID", {false, S::Bool, {S::Ptr, S::Ptr, S::I32, S::I32}}, [](NativeArgs& args) {
        if (const auto text = string_parameter(args, 1)) {
            store_string(args, 0, mid(*text, args.get<std::int32_t>(2), args.get<std::int32_t>(3)));
        }
    });
    // CONCAT is binary here: an n-ary call is folded left to right into its destination
    // (CONCAT(d, a, b); CONCAT(d, d, c)), which gives the same text since truncation keeps a
    // prefix.
    registry.add("CONCAT", {false, S::Bool, {S::Ptr, S::Ptr, S::Ptr}}, [](NativeArgs& args) {
        const auto a = string_parameter(args, 1);
        const auto b = a ? string_parameter(args, 2) : std::nullopt;
        if (b) {
            TextBuffer out;
            out.append(*a);
            out.append(*b);
            store_string(args, 0, out.view());
        }
    });
    // INSERT(IN1, IN2, P): IN2 after the first P characters of IN1; P is clamped to 0..LEN(IN1).
    registry.add("INSERT", {false, S::Bool, {S::Ptr, S::Ptr, S::Ptr, S::I32}},
                 [](NativeArgs& args) {
                     const auto text = string_parameter(args, 1);
                     const auto insert = text ? string_parameter(args, 2) : std::nullopt;
                     if (insert) {
                         const auto split = clamp_count(args.get<std::int32_t>(3), text->size());
                         TextBuffer out;
                         out.append(text->substr(0, split));
                         out.append(*insert);
                         out.append(text->substr(split));
                         store_string(args, 0, out.view());
                     }
                 });
    // DELETE(IN, L, P)
    registry.add(
        "DELETE", {false, S::Bool, {S::Ptr, S::Ptr, S::I32, S::I32}}, [](NativeArgs& args) {
            if (const auto text = string_parameter(args, 1)) {
                TextBuffer out;
                splice(out, *text, args.get<std::int32_t>(2), args.get<std::int32_t>(3), {});
                store_string(args, 0, out.view());
            }
        });
    // REPLACE(IN1, IN2, L, P)
    registry.add("REPLACE", {false, S::Bool, {S::Ptr, S::Ptr, S::Ptr, S::I32, S::I32}},
                 [](NativeArgs& args) {
                     const auto text = string_parameter(args, 1);
                     const auto insert = text ? string_parameter(args, 2) : std::nullopt;
                     if (insert) {
                         TextBuffer out;
                         splice(out, *text, args.get<std::int32_t>(3), args.get<std::int32_t>(4),
                                *insert);
                         store_string(args, 0, out.view());
                     }
                 });
    registry.add("FIND", {true, S::I32, {S::Ptr, S::Ptr}}, [](NativeArgs& args) {
        const auto haystack = string_parameter(args, 0);
        const auto needle = haystack ? string_parameter(args, 1) : std::nullopt;
        if (needle) {
            args.set_result(find(*haystack, *needle));
        }
    });
    add_comparison(registry, "EQ_STRING", [](std::strong_ordering o) { return o == 0; });
    add_comparison(registry, "NE_STRING", [](std::strong_ordering o) { return o != 0; });
    add_comparison(registry, "LT_STRING", [](std::strong_ordering o) { return o < 0; });
    add_comparison(registry, "LE_STRING", [](std::strong_ordering o) { return o <= 0; });
    add_comparison(registry, "GT_STRING", [](std::strong_ordering o) { return o > 0; });
    add_comparison(registry, "GE_STRING", [](std::strong_ordering o) { return o >= 0; });
}

} // namespace eposp::vm::stdlib
