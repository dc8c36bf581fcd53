// The IEC 61131-3 string functions (table 43), each called through CallNative in the
// interpreter: the examples of the standard, out-of-range positions and lengths, truncation at
// the destination's capacity, and a destination that is also an argument. Every table runs on
// STRING and on WSTRING (the same natives written once on the character type).

#include "stdlib_harness.hpp"

namespace eposp::vm::test {
namespace {

/// A WSTRING[capacity] holding `text` in static data; returns its offset.
std::uint32_t wstring(StdlibCall& call, std::uint32_t capacity, std::u16string_view text) {
    const auto bytes = stdlib::wstring_image(capacity, text);
    const auto offset = call.harness.builder.allocate(static_cast<std::uint32_t>(bytes.size()),
                                                      stdlib::kStringAlign);
    call.harness.builder.initialise(offset, bytes);
    return offset;
}

/// The units of the WSTRING at `offset` after the run, and its terminator.
std::u16string wtext(const StdlibCall& call, std::uint32_t offset) {
    const auto* at = call.harness.machine->memory().data() + offset;
    std::uint16_t length;
    std::memcpy(&length, at + 2, 2);
    std::u16string units(length + 1U, u'\0');
    std::memcpy(units.data(), at + stdlib::kStringHeaderSize, 2U * (length + 1U));
    return units;
}

/// Latin-1 text as UTF-16 units.
std::u16string widened(std::string_view text) {
    std::u16string units;
    for (const char c : text) {
        units.push_back(static_cast<char16_t>(static_cast<unsigned char>(c)));
    }
    return units;
}

/// The tables below name the STRING natives; the WSTRING ones are `LEFT_WSTRING`, `EQ_WSTRING`.
std::string native_for(std::string_view name, stdlib::CharWidth width) {
    if (width == stdlib::CharWidth::Narrow) {
        return std::string(name);
    }
    return name.ends_with("_STRING") ? std::string(name.substr(0, name.size() - 6)) + "WSTRING"
                                     : std::string(name) + "_WSTRING";
}

/// A STRING or WSTRING[capacity] holding the Latin-1 `text`; returns its offset.
std::uint32_t text_of(StdlibCall& call, stdlib::CharWidth width, std::uint32_t capacity,
                      std::string_view text) {
    return width == stdlib::CharWidth::Narrow ? call.string(capacity, text)
                                              : wstring(call, capacity, widened(text));
}

/// The text at `offset` after the run, as Latin-1 (a WSTRING without its terminator).
std::string text_at(const StdlibCall& call, stdlib::CharWidth width, std::uint32_t offset) {
    if (width == stdlib::CharWidth::Narrow) {
        return call.text(offset);
    }
    std::string text;
    for (const char16_t unit : wtext(call, offset)) {
        text.push_back(static_cast<char>(unit));
    }
    text.pop_back();
    return text;
}

auto both_widths() {
    return ::testing::Values(stdlib::CharWidth::Narrow, stdlib::CharWidth::Wide);
}

/// FUNCTION(dst, strings..., integers...) into a STRING[capacity].
struct StringResultCase {
    const char* label;
    const char* function;
    std::vector<std::string> strings;
    std::vector<std::int32_t> integers;
    std::string expected;
    std::uint32_t capacity = 80;
};

void PrintTo(const StringResultCase& c, std::ostream* os) {
    *os << c.label;
}

class StringResult
    : public ::testing::TestWithParam<std::tuple<StringResultCase, stdlib::CharWidth>> {};

TEST_P(StringResult, GivesTheIecResult) {
    const auto& [c, width] = GetParam();
    StdlibCall call;
    const auto destination = text_of(call, width, c.capacity, "old contents");
    std::vector<NativeArg> args{StdlibCall::string_arg(destination)};
    for (const auto& s : c.strings) {
        args.push_back(StdlibCall::string_arg(text_of(call, width, 80, s)));
    }
    for (const auto i : c.integers) {
        args.push_back(value(i));
    }
    ASSERT_EQ(call.call(native_for(c.function, width), args), RunState::Finished);
    EXPECT_EQ(text_at(call, width, destination), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    StandardExamples, StringResult,
    ::testing::Combine(
        ::testing::Values(StringResultCase{"LEFT", "LEFT", {"ASTR"}, {3}, "AST"},
                          StringResultCase{"RIGHT", "RIGHT", {"ASTR"}, {3}, "STR"},
                          StringResultCase{"MID", "MID", {"ASTR"}, {2, 2}, "ST"},
                          StringResultCase{"CONCAT", "CONCAT", {"AB", "CD"}, {}, "ABCD"},
                          StringResultCase{"INSERT", "INSERT", {"ABC", "XY"}, {2}, "ABXYC"},
                          StringResultCase{"DELETE", "DELETE", {"ABXYC"}, {2, 3}, "ABC"},
                          StringResultCase{"REPLACE", "REPLACE", {"ABCDE", "X"}, {2, 3}, "ABXE"},
                          StringResultCase{"ASSIGN", "ASSIGN_STRING", {"hello"}, {}, "hello"}),
        both_widths()));

INSTANTIATE_TEST_SUITE_P(
    OutOfRangeArguments, StringResult,
    ::testing::Combine(
        ::testing::Values(
            StringResultCase{"LEFT_longer_than_text", "LEFT", {"ABC"}, {10}, "ABC"},
            StringResultCase{"LEFT_negative", "LEFT", {"ABC"}, {-1}, ""},
            StringResultCase{"RIGHT_longer_than_text", "RIGHT", {"ABC"}, {10}, "ABC"},
            StringResultCase{"RIGHT_zero", "RIGHT", {"ABC"}, {0}, ""},
            StringResultCase{"MID_runs_past_end", "MID", {"ABC"}, {5, 2}, "BC"},
            StringResultCase{"MID_position_0", "MID", {"ABC"}, {2, 0}, ""},
            StringResultCase{"MID_position_past_end", "MID", {"ABC"}, {1, 4}, ""},
            StringResultCase{"MID_negative_length", "MID", {"ABC"}, {-2, 1}, ""},
            StringResultCase{"INSERT_at_0", "INSERT", {"ABC", "X"}, {0}, "XABC"},
            StringResultCase{"INSERT_negative_is_front", "INSERT", {"ABC", "X"}, {-3}, "XABC"},
            StringResultCase{"INSERT_past_end_appends", "INSERT", {"ABC", "X"}, {9}, "ABCX"},
            StringResultCase{"DELETE_runs_past_end", "DELETE", {"ABCDE"}, {10, 4}, "ABC"},
            StringResultCase{"DELETE_position_0_unchanged", "DELETE", {"ABC"}, {1, 0}, "ABC"},
            StringResultCase{"DELETE_position_past_end", "DELETE", {"ABC"}, {1, 4}, "ABC"},
            StringResultCase{"REPLACE_length_0_inserts", "REPLACE", {"ABC", "X"}, {0, 2}, "AXBC"},
            StringResultCase{"REPLACE_position_past_end", "REPLACE", {"ABC", "X"}, {1, 7}, "ABC"},
            StringResultCase{"CONCAT_empty", "CONCAT", {"", ""}, {}, ""}),
        both_widths()));

INSTANTIATE_TEST_SUITE_P(
    TruncatedToDestinationCapacity, StringResult,
    ::testing::Combine(
        ::testing::Values(StringResultCase{"CONCAT", "CONCAT", {"ABCD", "EFGH"}, {}, "ABCDEF", 6},
                          StringResultCase{"LEFT", "LEFT", {"ABCDEFGH"}, {8}, "ABC", 3},
                          StringResultCase{"INSERT", "INSERT", {"ABCD", "XY"}, {1}, "AXYB", 4},
                          StringResultCase{"ASSIGN", "ASSIGN_STRING", {"toolong"}, {}, "to", 2},
                          StringResultCase{"REPLACE", "REPLACE", {"ABCD", "WXYZ"}, {1, 1}, "W", 1}),
        both_widths()));

/// FUNCTION(strings...) giving a DINT or BOOL.
struct ScalarResultCase {
    const char* label;
    const char* function;
    std::vector<std::string> strings;
    std::int32_t expected;
};

void PrintTo(const ScalarResultCase& c, std::ostream* os) {
    *os << c.label;
}

class StringScalarResult
    : public ::testing::TestWithParam<std::tuple<ScalarResultCase, stdlib::CharWidth>> {};

TEST_P(StringScalarResult, GivesTheIecResult) {
    const auto& [c, width] = GetParam();
    StdlibCall call;
    std::vector<NativeArg> args;
    for (const auto& s : c.strings) {
        args.push_back(StdlibCall::string_arg(text_of(call, width, 80, s)));
    }
    const auto native = native_for(c.function, width);
    ASSERT_EQ(call.call(native, args), RunState::Finished);
    const bool is_bool = call.harness.natives.find(native)->signature.result == Scalar::Bool;
    EXPECT_EQ(is_bool ? call.result<std::uint8_t>() : call.result<std::int32_t>(), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    LengthAndSearch, StringScalarResult,
    ::testing::Combine(
        ::testing::Values(ScalarResultCase{"LEN", "LEN", {"ASTRING"}, 7},
                          ScalarResultCase{"LEN_empty", "LEN", {""}, 0},
                          ScalarResultCase{"FIND", "FIND", {"ABCBC", "BC"}, 2},
                          ScalarResultCase{"FIND_absent", "FIND", {"ABC", "X"}, 0},
                          ScalarResultCase{"FIND_longer_needle", "FIND", {"AB", "ABC"}, 0},
                          ScalarResultCase{"FIND_empty_needle", "FIND", {"ABC", ""}, 0}),
        both_widths()));

INSTANTIATE_TEST_SUITE_P(
    Comparisons, StringScalarResult,
    ::testing::Combine(
        ::testing::Values(ScalarResultCase{"EQ_same", "EQ_STRING", {"abc", "abc"}, 1},
                          ScalarResultCase{"EQ_prefix", "EQ_STRING", {"abc", "ab"}, 0},
                          ScalarResultCase{"NE", "NE_STRING", {"abc", "abd"}, 1},
                          ScalarResultCase{"LT_prefix_first", "LT_STRING", {"ab", "abc"}, 1},
                          ScalarResultCase{"LT_bytes_unsigned", "LT_STRING", {"z", "\xE4"}, 1},
                          ScalarResultCase{"LE_equal", "LE_STRING", {"b", "b"}, 1},
                          ScalarResultCase{"GT_case", "GT_STRING", {"a", "B"}, 1},
                          ScalarResultCase{"GE_less", "GE_STRING", {"a", "b"}, 0}),
        both_widths()));

class CharacterConversion : public ::testing::TestWithParam<stdlib::CharWidth> {};

TEST_P(CharacterConversion, CharacterToStringMakesAOneCharacterString) {
    const auto width = GetParam();
    StdlibCall call;
    const auto destination = text_of(call, width, 4, "old");
    const bool wide = width == stdlib::CharWidth::Wide;
    ASSERT_EQ(call.call(wide ? "WCHAR_TO_WSTRING" : "CHAR_TO_STRING",
                        {StdlibCall::string_arg(destination),
                         wide ? value(std::uint16_t{'x'}) : value(std::uint8_t{'x'})}),
              RunState::Finished);
    EXPECT_EQ(text_at(call, width, destination), "x");
}

TEST_P(CharacterConversion, StringToCharacterTakesTheFirstOrZero) {
    const auto width = GetParam();
    const auto native = width == stdlib::CharWidth::Wide ? "WSTRING_TO_WCHAR" : "STRING_TO_CHAR";
    for (const auto& [text, expected] : {std::pair{"\xE9t\xE9", 0xE9}, std::pair{"", 0}}) {
        StdlibCall call;
        ASSERT_EQ(call.call(native, {StdlibCall::string_arg(text_of(call, width, 8, text))}),
                  RunState::Finished);
        EXPECT_EQ(width == stdlib::CharWidth::Wide ? call.result<std::uint16_t>()
                                                   : call.result<std::uint8_t>(),
                  expected)
            << text;
    }
}

INSTANTIATE_TEST_SUITE_P(BothWidths, CharacterConversion, both_widths());

TEST(StringFunctions, NaryConcatFoldsIntoItsDestination) {
    StdlibCall call;
    const auto d = call.string(10);
    const auto a = call.string_arg(80, "Axis");
    const auto b = call.string_arg(80, "-");
    const auto c = call.string_arg(80, "12345678");
    call.emit_call("CONCAT", {StdlibCall::string_arg(d), a, b});
    call.emit_call("CONCAT", {StdlibCall::string_arg(d), StdlibCall::string_arg(d), c});
    ASSERT_EQ(call.run(), RunState::Finished);
    EXPECT_EQ(call.text(d), "Axis-12345");
}

TEST(StringFunctions, DestinationMayAlsoBeTheArgument) {
    StdlibCall call;
    const auto s = call.string(20, "ABCDEF");
    const auto x = call.string_arg(80, "xy");
    call.emit_call("REPLACE", {StdlibCall::string_arg(s), StdlibCall::string_arg(s), x,
                               value(std::int32_t{2}), value(std::int32_t{2})});
    call.emit_call("MID", {StdlibCall::string_arg(s), StdlibCall::string_arg(s),
                           value(std::int32_t{4}), value(std::int32_t{2})});
    ASSERT_EQ(call.run(), RunState::Finished);
    EXPECT_EQ(call.text(s), "xyDE");
}

TEST(StringFunctions, NullStringPointerStopsTheTaskWithAReason) {
    StdlibCall call;
    ASSERT_EQ(call.call("LEN", {value(std::uint64_t{0})}), RunState::Faulted);
    const auto& task = call.harness.machine->task(0);
    EXPECT_EQ(task.fault.trap, Trap::NativeError);
    EXPECT_NE(task.fault.native_reason.find("NULL"), std::string::npos);
}

TEST(StringFunctions, PointerToSomethingElseIsRefused) {
    StdlibCall call;
    const auto not_a_string =
        call.harness.builder.constant(std::uint32_t{0x0009'0005}); // length 9 > capacity 5
    ASSERT_EQ(call.call("LEN", {value(std::uint64_t{not_a_string})}), RunState::Faulted);
    EXPECT_EQ(call.harness.machine->task(0).fault.trap, Trap::NativeError)
        << call.harness.machine->describe_fault(0);
}

TEST(WstringFunctions, LenCountsUtf16Units) {
    StdlibCall call;
    const auto w = wstring(call, 10, u"\u00c4x\u20ac");
    ASSERT_EQ(call.call("LEN_WSTRING", {StdlibCall::string_arg(w)}), RunState::Finished);
    EXPECT_EQ(call.result<std::int32_t>(), 3);
}

TEST(WstringFunctions, ToStringKeepsLatin1AndMarksTheRest) {
    StdlibCall call;
    const auto w = wstring(call, 10, u"A\u00e4\u20acZ");
    const auto s = call.string(3);
    ASSERT_EQ(
        call.call("WSTRING_TO_STRING", {StdlibCall::string_arg(s), StdlibCall::string_arg(w)}),
        RunState::Finished);
    EXPECT_EQ(call.text(s), "A\xE4?");
}

TEST(WstringFunctions, FromStringWidensAndTruncates) {
    StdlibCall call;
    const auto w = wstring(call, 4, u"old");
    ASSERT_EQ(
        call.call("STRING_TO_WSTRING", {StdlibCall::string_arg(w), call.string_arg(80, "ab\xE9"
                                                                                       "cdef")}),
        RunState::Finished);
    EXPECT_EQ(wtext(call, w), std::u16string(u"ab\u00e9c\0", 5));
}

TEST(WstringFunctions, InconsistentHeaderIsRefused) {
    StdlibCall call;
    const auto not_a_wstring = call.harness.builder.constant(std::uint32_t{0x0003'0002});
    ASSERT_EQ(call.call("LEN_WSTRING", {value(std::uint64_t{not_a_wstring})}), RunState::Faulted);
    EXPECT_EQ(call.harness.machine->task(0).fault.native_reason,
              "pointer does not point to a WSTRING");
}

TEST(WstringFunctions, PositionsCountUtf16UnitsBeyondLatin1) {
    StdlibCall call;
    const auto text = wstring(call, 10, u"a\u20acb\u4e2dc");
    const auto part = wstring(call, 10, u"old");
    call.emit_call("MID_WSTRING", {StdlibCall::string_arg(part), StdlibCall::string_arg(text),
                                   value(std::int32_t{3}), value(std::int32_t{2})});
    ASSERT_EQ(call.run(), RunState::Finished);
    EXPECT_EQ(wtext(call, part), std::u16string(u"\u20acb\u4e2d\0", 4));
}

TEST(WstringFunctions, FindGivesTheUnitPosition) {
    StdlibCall call;
    const auto haystack = wstring(call, 10, u"\u4e2d\u6587\u20ac");
    const auto needle = wstring(call, 10, u"\u20ac");
    ASSERT_EQ(call.call("FIND_WSTRING",
                        {StdlibCall::string_arg(haystack), StdlibCall::string_arg(needle)}),
              RunState::Finished);
    EXPECT_EQ(call.result<std::int32_t>(), 3);
}

TEST(WstringFunctions, ComparisonOrdersUnitsAsUnsigned16Bit) {
    StdlibCall call;
    const auto euro = wstring(call, 4, u"\u20ac");
    const auto a_umlaut = wstring(call, 4, u"\u00e4");
    ASSERT_EQ(
        call.call("GT_WSTRING", {StdlibCall::string_arg(euro), StdlibCall::string_arg(a_umlaut)}),
        RunState::Finished);
    EXPECT_EQ(call.result<std::uint8_t>(), 1);
}

} // namespace
} // namespace eposp::vm::test
