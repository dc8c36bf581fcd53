#include "source_token.hpp"

#include <CharStream.h>
#include <misc/Interval.h>

namespace eposp::compiler {

static_assert(sizeof(SourceToken) == 48);

// As CommonToken::getText: the input's text, "<EOF>" past its end.
std::string SourceToken::getText() const {
    antlr4::CharStream* input = getInputStream();
    const std::size_t size = input->size();
    if (start_ < size && stop_ < size) {
        return input->getText(antlr4::misc::Interval(start_, stop_));
    }
    return "<EOF>";
}

std::string SourceToken::toString() const {
    return "[@" + std::to_string(index_) + "," + std::to_string(start_) + ":" +
           std::to_string(stop_) + "='" + getText() + "',<" + std::to_string(getType()) + ">" +
           (channel_ > 0 ? ",channel=" + std::to_string(channel_) : "") + "," +
           std::to_string(line_) + ":" + std::to_string(column_) + "]";
}

} // namespace eposp::compiler
