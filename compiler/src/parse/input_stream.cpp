#include "input_stream.hpp"

#include "../utf8.hpp"
#include "ascii_prefix.hpp"

#include <misc/Interval.h>

namespace eposp::compiler {

// As the runtime's load(), which drops a leading byte order mark, but decoded in one pass into a
// string of the right size: the runtime converts through std::wstring_convert, slowly, into a
// string sized for the longest conversion, five times what it keeps.
InputStream::InputStream(const std::string& text) {
    std::string_view bytes(text);
    if (bytes.starts_with("\xEF\xBB\xBF")) {
        bytes.remove_prefix(3);
    }
    // At most one code point a byte; cut to what the text holds at the end.
    _data.resize(bytes.size());
    const std::size_t ascii = ascii_prefix(bytes);
    char32_t* next = _data.data();
    for (std::size_t i = 0; i < ascii; ++i) {
        *next++ = static_cast<unsigned char>(bytes[i]);
    }
    for (std::size_t i = ascii; i < bytes.size();) {
        const auto byte = static_cast<unsigned char>(bytes[i]);
        if (byte < 0x80) { // ASCII, nearly every byte: no call
            *next++ = byte;
            ++i;
        } else {
            *next++ = utf8::decode(bytes, i).value_or(U'\uFFFD');
        }
    }
    _data.resize(static_cast<std::size_t>(next - _data.data()));
}

// The runtime converts every text from UTF-32 through std::wstring_convert. The copy has no
// branch a character, so that it vectorises; whether all were ASCII is looked at after it.
std::string InputStream::text(std::size_t start, std::size_t stop) {
    const char32_t* from = _data.data() + start;
    std::string text(stop - start + 1, '\0');
    char32_t all = 0;
    for (char& c : text) {
        all |= *from;
        c = static_cast<char>(*from++);
    }
    if (all >= 0x80) {
        return ANTLRInputStream::getText(antlr4::misc::Interval(start, stop));
    }
    return text;
}

std::string InputStream::getText(const antlr4::misc::Interval& interval) {
    if (interval.a < 0 || interval.b < interval.a ||
        static_cast<std::size_t>(interval.b) >= _data.size()) {
        return ANTLRInputStream::getText(interval);
    }
    return text(static_cast<std::size_t>(interval.a), static_cast<std::size_t>(interval.b));
}

} // namespace eposp::compiler
