#pragma once

// STRING parameters of native calls: a string is passed as a pointer (Scalar::Ptr) to its header
// (string_layout.hpp), a string result as a pointer to the destination in parameter 0. Every
// pointer is checked against VM memory and the header it points to before use.

#include "eposp/vm/native.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace eposp::vm::stdlib {

/// The whole STRING or WSTRING (header included) parameter `index` points to; empty after
/// failing the call if the pointer is NULL, outside memory or not at a consistent header.
std::span<std::uint8_t> string_bytes(NativeArgs& args, std::size_t index, CharWidth width);

/// The text of STRING parameter `index`; fails the call (and returns nothing) if the pointer is
/// NULL, outside memory or not at a consistent string header.
std::optional<std::string_view> string_parameter(NativeArgs& args, std::size_t index);

/// Stores `text` into the STRING that parameter `index` points to, cut at its capacity. `text`
/// may lie anywhere in VM memory, including inside the destination.
void store_string(NativeArgs& args, std::size_t index, std::string_view text);

/// A result assembled from several pieces that may overlap the destination; cut at the longest
/// capacity a STRING can have. Lives on the host stack: natives never allocate.
class TextBuffer {
public:
    void append(std::string_view piece);
    std::string_view view() const { return {chars_.data(), size_}; }

private:
    std::array<char, kMaxStringCapacity> chars_;
    std::size_t size_ = 0;
};

} // namespace eposp::vm::stdlib
