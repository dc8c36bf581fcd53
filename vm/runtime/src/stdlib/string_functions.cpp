// IEC 61131-3 (3rd ed.) 6.6.2.5.12, table 43: the character string functions, written once on
// the character type and registered for STRING (`LEFT`, `EQ_STRING`) and WSTRING
// (`LEFT_WSTRING`, `EQ_WSTRING`). What each computes is text_functions.hpp's, which the compiler
// folds constants with; here the inputs are read from and the result stored into VM memory.

#include "eposp/vm/stdlib/text_functions.hpp"
#include "library_parts.hpp"
#include "string_arguments.hpp"

#include <compare>
#include <string>

namespace eposp::vm::stdlib {
namespace {

/// Stores the result `pieces` make into the string parameter 0 points to, cut at its capacity.
/// Assembled first: a piece may lie inside the destination.
template <typename Char>
void store_pieces(NativeArgs& args, const TextPieces<Char>& pieces) {
    TextBuffer<Char> out;
    for (const Text<Char> piece : pieces) {
        out.append(piece);
    }
    store_text(args, 0, out.view());
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

// EQ_STRING ... GE_WSTRING: whether the texts' order (text_order) `holds`.
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
                args.set_result(static_cast<std::uint8_t>(holds(text_order(a.view(), b.view()))));
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
            store_text(args, 0, left_of(text.view(), args.get<std::int32_t>(2)));
        }
    });
    add_standard(registry, native_binding("RIGHT", N::kVariant), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 1); text) {
            store_text(args, 0, right_of(text.view(), args.get<std::int32_t>(2)));
        }
    });
    // MID(IN, L, P)
    add_standard(registry, native_binding("MID", N::kVariant), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 1); text) {
            store_text(args, 0,
                       mid_of(text.view(), args.get<std::int32_t>(2), args.get<std::int32_t>(3)));
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
            store_pieces(args, concat_of(a.view(), b.view()));
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
            store_pieces(args, insert_of(text.view(), insert.view(), args.get<std::int32_t>(3)));
        }
    });
    // DELETE(IN, L, P)
    add_standard(registry, native_binding("DELETE", N::kVariant), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 1); text) {
            store_pieces(args, replace_of(text.view(), View{}, args.get<std::int32_t>(2),
                                          args.get<std::int32_t>(3)));
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
            store_pieces(args, replace_of(text.view(), insert.view(), args.get<std::int32_t>(3),
                                          args.get<std::int32_t>(4)));
        }
    });
    add_standard(registry, native_binding("FIND", N::kVariant), [](NativeArgs& args) {
        const StringParameter<Char> haystack(args, 0);
        if (!haystack) {
            return;
        }
        const StringParameter<Char> needle(args, 1);
        if (needle) {
            args.set_result(find_in(haystack.view(), needle.view()));
        }
    });
    // Table 22: CHAR_TO_STRING(dst, c) is the string of that one character, STRING_TO_CHAR(s)
    // its first character (first_character); the same for WCHAR and WSTRING.
    add_standard(registry, to_text_binding(N::kCharacter, kWidthOf<Char>), [](NativeArgs& args) {
        const auto character = static_cast<Char>(args.get<typename N::CharacterCode>(1));
        store_text(args, 0, View{&character, 1});
    });
    add_standard(registry, from_text_binding(N::kCharacter, kWidthOf<Char>), [](NativeArgs& args) {
        if (const StringParameter<Char> text(args, 0); text) {
            using Code = typename N::CharacterCode;
            args.set_result(static_cast<Code>(first_character(text.view())));
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
