// The conversions between WSTRING and STRING (the other string functions are shared,
// string_functions.cpp), character by character as text_functions.hpp converts one.

#include "eposp/vm/stdlib/text_functions.hpp"
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
            const char c = narrow_character(unit);
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
            const char16_t unit = wide_character(c);
            units.append({&unit, 1});
        }
        store_text(args, 0, units.view());
    });
}

} // namespace eposp::vm::stdlib
