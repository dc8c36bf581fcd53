// The STRING / WSTRING memory layout codegen relies on (vm/README.md, "Strings").

#include "eposp/vm/stdlib/string_layout.hpp"

#include <gtest/gtest.h>

namespace eposp::vm::stdlib {
namespace {

TEST(StringLayout, HeaderThenCharactersThenNul) {
    const auto bytes = string_image(5, "abc");
    const std::vector<std::uint8_t> expected{5, 0, 3, 0, 'a', 'b', 'c', 0, 0, 0};
    EXPECT_EQ(bytes, expected);
    EXPECT_EQ(string_size(5), 10U);
}

TEST(StringLayout, InitialValueIsCutAtTheCapacity) {
    const auto bytes = string_image(2, "abc");
    EXPECT_EQ(read_string(bytes), "ab");
    EXPECT_EQ(bytes.back(), 0);
}

TEST(StringLayout, WstringHoldsUtf16UnitsAndAWideNul) {
    const auto bytes = wstring_image(2, u"\u20ac");
    const std::vector<std::uint8_t> expected{2, 0, 1, 0, 0xAC, 0x20, 0, 0, 0, 0};
    EXPECT_EQ(bytes, expected);
    EXPECT_EQ(string_size(2, CharWidth::Wide), 10U);
}

TEST(StringLayout, InconsistentOrCutHeadersAreNotStrings) {
    const std::vector<std::uint8_t> length_above_capacity{2, 0, 3, 0, 'a', 'b', 0};
    const std::vector<std::uint8_t> zero_capacity{0, 0, 0, 0, 0};
    const auto whole = string_image(4, "ab");
    EXPECT_FALSE(read_string(length_above_capacity));
    EXPECT_FALSE(read_string(zero_capacity));
    EXPECT_FALSE(read_string(std::span(whole).first(whole.size() - 1)));
    EXPECT_EQ(string_capacity(whole), 4);
}

// A capacity above the longest string (32767, so that LEN's INT holds every length) is no
// string even where the bytes are there: a native counting it would give a negative INT.
TEST(StringLayout, ACapacityAboveTheLongestStringIsNoString) {
    std::vector<std::uint8_t> bytes(kStringHeaderSize + 40001, 'x');
    bytes[0] = 40000 & 0xFF;
    bytes[1] = 40000 >> 8;
    bytes[2] = 40000 & 0xFF;
    bytes[3] = 40000 >> 8;
    EXPECT_FALSE(string_capacity(bytes));
    EXPECT_FALSE(read_string(bytes));
    EXPECT_THROW(string_image(kMaxStringCapacity + 1, ""), std::logic_error);
    EXPECT_EQ(string_capacity(string_image(kMaxStringCapacity, "")), 32767);
}

TEST(StringLayout, WritingMayReadFromTheStringItself) {
    auto bytes = string_image(8, "abcdef");
    const auto text = *read_string(bytes);
    EXPECT_EQ(write_string(bytes, text.substr(2)), 4);
    EXPECT_EQ(read_string(bytes), "cdef");
    EXPECT_EQ(bytes[4 + 4], 0);
}

} // namespace
} // namespace eposp::vm::stdlib
