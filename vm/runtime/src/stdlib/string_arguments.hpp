#pragma once

// STRING and WSTRING parameters of native calls: a string is passed as a pointer (Scalar::Ptr) to
// its header (string_layout.hpp), a string result as a pointer to the destination in parameter 0.
// Every pointer is checked against VM memory and the header it points to before use. The string
// functions are written once for both, on the character type: `char` for STRING (Latin-1
// bytes), `char16_t` for WSTRING (UTF-16 units).

#include "eposp/vm/native.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

namespace eposp::vm::stdlib {

template <typename Char>
inline constexpr CharWidth kWidthOf = sizeof(Char) == 1 ? CharWidth::Narrow : CharWidth::Wide;

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
/// capacity a string can have. Lives on the host stack: natives never allocate.
template <typename Char>
class TextBuffer {
public:
    void append(std::basic_string_view<Char> piece) {
        const auto count = std::min(piece.size(), chars_.size() - size_);
        std::copy_n(piece.begin(), count, chars_.begin() + static_cast<std::ptrdiff_t>(size_));
        size_ += count;
    }
    std::basic_string_view<Char> view() const { return {chars_.data(), size_}; }

private:
    std::array<Char, kMaxStringCapacity> chars_;
    std::size_t size_ = 0;
};

/// The text of the STRING (Char = char) or WSTRING (char16_t) parameter `index`. A STRING is
/// viewed where it lies in VM memory; a WSTRING's units are copied out, since VM memory holds
/// bytes that may not be read as char16_t in place.
template <typename Char>
class StringParameter {
public:
    /// Fails the call (and tests false) if the pointer is NULL, outside memory or not at a
    /// consistent header.
    StringParameter(NativeArgs& args, std::size_t index);
    explicit operator bool() const { return valid_; }
    std::basic_string_view<Char> view() const {
        if constexpr (std::is_same_v<Char, char>) {
            return text_;
        } else {
            return text_.view();
        }
    }

private:
    std::conditional_t<std::is_same_v<Char, char>, std::string_view, TextBuffer<char16_t>> text_;
    bool valid_ = false;
};

/// Stores `text` into the string of character type Char that parameter `index` points to, cut
/// at its capacity.
template <typename Char>
void store_text(NativeArgs& args, std::size_t index, std::basic_string_view<Char> text);

} // namespace eposp::vm::stdlib
