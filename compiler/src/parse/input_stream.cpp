#include "input_stream.hpp"

namespace eposp::compiler {

// The runtime converts the text to UTF-32 into a string sized for the longest conversion, about
// five times what it keeps; its spare capacity would stay allocated while the file is parsed.
InputStream::InputStream(const std::string& text) : ANTLRInputStream(text) {
    _data.shrink_to_fit();
}

// The runtime converts every text from UTF-32 through std::wstring_convert.
std::string InputStream::getText(const antlr4::misc::Interval& interval) {
    if (interval.a < 0 || interval.b < interval.a ||
        static_cast<std::size_t>(interval.b) >= _data.size()) {
        return ANTLRInputStream::getText(interval);
    }
    std::string text;
    text.reserve(static_cast<std::size_t>(interval.b - interval.a + 1));
    for (ssize_t i = interval.a; i <= interval.b; ++i) {
        const char32_t c = _data[static_cast<std::size_t>(i)];
        if (c >= 0x80) {
            return ANTLRInputStream::getText(interval);
        }
        text.push_back(static_cast<char>(c));
    }
    return text;
}

} // namespace eposp::compiler
