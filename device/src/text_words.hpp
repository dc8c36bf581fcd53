#pragma once

// The small word-level reading shared by the one-line texts of the network file and of ST
// attributes (events, wires).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::device {

/// The words of `text`, split at white space.
std::vector<std::string> words_of(std::string_view text);

/// `word` in lower case (ASCII).
std::string lower(std::string word);

/// `word` as a decimal number, none if it is anything else.
std::optional<unsigned> number(const std::string& word);

} // namespace eposp::device
