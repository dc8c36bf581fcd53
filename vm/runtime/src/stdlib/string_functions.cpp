// IEC 61131-3 (3rd ed.) 6.6.2.5.12, table 43: the character string functions, written once on
// the character type and registered for STRING (`LEFT`, `EQ_STRING`) and WSTRING
// (`LEFT_WSTRING`, `EQ_WSTRING`). Positions are 1-based and count characters (UTF-16 units in a
// WSTRING). Where the standard leaves out-of-range arguments open, the result is the part of the
// request that exists (CODESYS behaves so for LEFT/RIGHT/MID): lengths below 0 count as 0,
// lengths past the end are cut, and a position outside the string selects nothing (MID, DELETE,
// REPLACE) or is clamped to the nearest end (INSERT).

#include "library_parts.hpp"
#include "string_arguments.hpp"

#include <algorithm>
#include <compare>
#include <string>

namespace eposp::vm::stdlib {
namespace {

/// `count` clamped to 0..limit.
std::size_t clamp_count(std::int32_t count, std::size_t limit) {
    return count <= 0 ? 0 : std::min<std::size_t>(static_cast<std::size_t>(count), limit);
}

/// The 0-based index of 1-based position `position` if it names a character of `text`.
template <typename Char>
std::optional<std::size_t> index_of(std::basic_string_view<Char> text, std::int32_t position) {
    if (position < 1 || static_cast<std::size_t>(position) > text.size()) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(position - 1);
}

template <typename Char>
std::basic_string_view<Char> mid(std::basic_string_view<Char> text, std::int32_t length,
                                 std::int32_t position) {
    const auto start = index_of(text, position);
    return start ? text.substr(*start, clamp_count(length, text.size() - *start))
                 : std::basic_string_view<Char>{};
}

/// `text` with `length` characters from `position` replaced by `insert`.
template <typename Char>
void splice(TextBuffer<Char>& out, std::basic_string_view<Char> text, std::int32_t length,
            std::int32_t position, std::basic_string_view<Char> insert) {
    const auto start = index_of(text, position);
    if (!start) {
        out.append(text);
        return;
    }
    out.append(text.substr(0, *start));
    out.append(insert);
    out.append(text.substr(*start + clamp_count(length, text.size() - *start)));
}

template <typename Char>
std::int32_t find(std::basic_string_view<Char> haystack, std::basic_string_view<Char> needle) {
    if (needle.empty()) {
        return 0;
    }
    const auto at = haystack.find(needle);
    return at == std::basic_string_view<Char>::npos ? 0 : static_cast<std::int32_t>(at + 1);
}

/// The natives of one string type, all bound as the manifest describes them: the standard
/// functions (`LEFT`, `LEFT_WSTRING`), the helpers (`EQ_STRING`, `ASSIGN_WSTRING`) and the
/// character conversions (`CHAR_TO_STRING`, `WSTRING_TO_WCHAR`).
template <typename Char>
struct Names {
    static constexpr bool kWide = std::is_same_v<Char, char16_t>;
    static constexpr Variant kVariant = kWide ? Variant::Wide : Variant::Base;
    static constexpr NativeType kCharacter = kWide ? NativeType::Wchar : NativeType::Char;
    /// How a CHAR / WCHAR is passed: its unsigned code.
    using CharacterCode = std::conditional_t<kWide, std::uint16_t, std::uint8_t>;
};

// Lexicographic order of the character codes as unsigned numbers, as CODESYS compares
// (char_traits compares char as unsigned char and char16_t as an unsigned 16-bit code).
template <typename Char>
void add_comparison(NativeRegistry& registry, Operation operation,
                    bool (*holds)(std::strong_ordering)) {
    add_standard(
        registry, text_comparison_binding(operation, kWidthOf<Char>), [holds](NativeArgs& args) {
            const StringParameter<Char> a(args, 0);
            if (!a) {
                return;
            }
            const StringParameter<Char> b(args, 1);
            if (b) {
                args.set_result(static_cast<std::uint8_t>(holds(a.view().compare(b.view()) <=> 0)));
            }
        });
}

template <typename Char>
void register_functions_of(NativeRegistry& registry) {
    using N = Names<Char>;
    using View = std::basic_string_view<Char>;
    // LEN reads the header alone: no need to copy a WSTRING's units.
    add_standard(registry, native_binding("LEN", N::kVariant), [](NativeArgs& args) {
        const auto bytes = string_bytes(args, 0, kWidthOf<Char>);
        if (!bytes.empty()) {
            args.set_result(static_cast<std::int32_t>(string_length(bytes)));
        }
    });
    // ASSIGN_STRING(dst, src): `dst := src` between strings of different capacities.
    add_standard(registry, text_assignment_binding(kWidthOf<Char>), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 1); text) {
            store_text(args, 0, text.view());
        }
    });
    add_standard(registry, native_binding("LEFT", N::kVariant), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 1); text) {
            const View in = text.view();
            store_text(args, 0, in.substr(0, clamp_count(args.get<std::int32_t>(2), in.size())));
        }
    });
    add_standard(registry, native_binding("RIGHT", N::kVariant), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 1); text) {
            const View in = text.view();
            const auto count = clamp_count(args.get<std::int32_t>(2), in.size());
            store_text(args, 0, in.substr(in.size() - count));
        }
    });
    // MID(IN, L, P)
    add_standard(registry, native_binding("MID", N::kVariant), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 1); text) {
            store_text(args, 0,
                       mid(text.view(), args.get<std::int32_t>(2), args.get<std::int32_t>(3)));
        }
    });
    // CONCAT is binary here: an n-ary call is folded left to right into its destination
    // (CONCAT(d, a, b); CONCAT(d, d, c)), which gives the same text since truncation keeps a
    // prefix.
    add_standard(registry, native_binding("CONCAT", N::kVariant), [](NativeArgs& args) {
        const StringParameter<Char> a(args, 1);
        if (!a) {
            return;
        }
        const StringParameter<Char> b(args, 2);
        if (b) {
            TextBuffer<Char> out;
            out.append(a.view());
            out.append(b.view());
            store_text(args, 0, out.view());
        }
    });
    // INSERT(IN1, IN2, P): IN2 after the first P characters of IN1; P is clamped to 0..LEN(IN1).
    add_standard(registry, native_binding("INSERT", N::kVariant), [](NativeArgs& args) {
        const StringParameter<Char> text(args, 1);
        if (!text) {
            return;
        }
        const StringParameter<Char> insert(args, 2);
        if (insert) {
            const View in = text.view();
            const auto split = clamp_count(args.get<std::int32_t>(3), in.size());
            TextBuffer<Char> out;
            out.append(in.substr(0, split));
            out.append(insert.view());
            out.append(in.substr(split));
            store_text(args, 0, out.view());
        }
    });
    // DELETE(IN, L, P)
    add_standard(registry, native_binding("DELETE", N::kVariant), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 1); text) {
            TextBuffer<Char> out;
            splice(out, text.view(), args.get<std::int32_t>(2), args.get<std::int32_t>(3), View{});
            store_text(args, 0, out.view());
        }
    });
    // REPLACE(IN1, IN2, L, P)
    add_standard(registry, native_binding("REPLACE", N::kVariant), [](NativeArgs& args) {
        const StringParameter<Char> text(args, 1);
        if (!text) {
            return;
        }
        const StringParameter<Char> insert(args, 2);
        if (insert) {
            TextBuffer<Char> out;
            splice(out, text.view(), args.get<std::int32_t>(3), args.get<std::int32_t>(4),
                   insert.view());
            store_text(args, 0, out.view());
        }
    });
    add_standard(registry, native_binding("FIND", N::kVariant), [](NativeArgs& args) {
        const StringParameter<Char> haystack(args, 0);
        if (!haystack) {
            return;
        }
        const StringParameter<Char> needle(args, 1);
        if (needle) {
            args.set_result(find(haystack.view(), needle.view()));
        }
    });
    // Table 22: CHAR_TO_STRING(dst, c) is the string of that one character, STRING_TO_CHAR(s)
    // its first character, or 0 when it is empty (as CODESYS); the same for WCHAR and WSTRING.
    add_standard(registry, to_text_binding(N::kCharacter, kWidthOf<Char>), [](NativeArgs& args) {
        const auto character = static_cast<Char>(args.get<typename N::CharacterCode>(1));
        store_text(args, 0, View{&character, 1});
    });
    add_standard(registry, from_text_binding(N::kCharacter, kWidthOf<Char>), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 0); text) {
            using Code = typename N::CharacterCode;
            args.set_result(text.view().empty() ? Code{0} : static_cast<Code>(text.view()[0]));
        }
    });
    using Op = Operation;
    add_comparison<Char>(registry, Op::Equal, [](std::strong_ordering o) { return o == 0; });
    add_comparison<Char>(registry, Op::NotEqual, [](std::strong_ordering o) { return o != 0; });
    add_comparison<Char>(registry, Op::Less, [](std::strong_ordering o) { return o < 0; });
    add_comparison<Char>(registry, Op::LessEqual, [](std::strong_ordering o) { return o <= 0; });
    add_comparison<Char>(registry, Op::Greater, [](std::strong_ordering o) { return o > 0; });
    add_comparison<Char>(registry, Op::GreaterEqual, [](std::strong_ordering o) { return o >= 0; });
}

} // namespace

void register_string_functions(NativeRegistry& registry) {
    register_functions_of<char>(registry);
    register_functions_of<char16_t>(registry);
}

} // namespace eposp::vm::stdlib
