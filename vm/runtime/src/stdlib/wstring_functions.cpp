// The conversions between WSTRING and STRING (the other string functions are shared,
// string_functions.cpp). STRING characters are Latin-1 (CODESYS's default code page); a UTF-16
// unit above 255 has no STRING character and becomes '?', as in CODESYS's WSTRING_TO_STRING.

#include "library_parts.hpp"
#include "string_arguments.hpp"

namespace eposp::vm::stdlib {

void register_wstring_functions(NativeRegistry& registry) {
    add_standard(registry, text_width_binding(CharWidth::Narrow), [](NativeArgs& args) {
        const StringParameter<char16_t> source(args, 1);
        if (!source) {
            return;
        }
        TextBuffer<char> text;
        for (const char16_t unit : source.view()) {
            const char c = unit <= 0xFF ? static_cast<char>(unit) : '?';
            text.append({&c, 1});
        }
        store_string(args, 0, text.view());
    });
    add_standard(registry, text_width_binding(CharWidth::Wide), [](NativeArgs& args) {
        const auto source = string_parameter(args, 1);
        if (!source) {
            return;
        }
        TextBuffer<char16_t> units;
        for (const char c : *source) {
            const auto unit = static_cast<char16_t>(static_cast<unsigned char>(c));
            units.append({&unit, 1});
        }
        store_text(args, 0, units.view());
    });
}

} // namespace eposp::vm::stdlib
