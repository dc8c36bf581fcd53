#pragma once

// Frames for the framing tests: random ones from a seeded generator (reproducible), and byte
// strings written as the guide writes them.

#include "eposp/service/frame.hpp"

#include <cstdint>
#include <initializer_list>
#include <random>
#include <vector>

namespace eposp::service::test {

using Bytes = std::vector<std::uint8_t>;

inline Bytes bytes(std::initializer_list<int> values) {
    Bytes out;
    for (const int value : values) {
        out.push_back(static_cast<std::uint8_t>(value));
    }
    return out;
}

/// A frame of `min_words` to `max_words` words; `dle_share` of its bytes (opcode included) are
/// 0x90, the byte that v2 stuffs.
inline Frame random_frame(std::mt19937& random, std::size_t min_words, std::size_t max_words,
                          double dle_share = 0.0) {
    std::uniform_int_distribution<std::size_t> words(min_words, max_words);
    std::uniform_int_distribution<int> byte(0, 255);
    std::bernoulli_distribution dle(dle_share);
    const auto next = [&] {
        return static_cast<std::uint8_t>(dle(random) ? 0x90 : byte(random));
    };
    Frame frame;
    frame.opcode = next();
    frame.data.resize(2 * words(random));
    for (auto& value : frame.data) {
        value = next();
    }
    return frame;
}

} // namespace eposp::service::test
