// Values shown as IEC 61131-3 literals, by the type the image gives the variable.

#include "eposp/vm/stdlib/string_layout.hpp"
#include "eposp/vm/value_format.hpp"

#include <cstring>
#include <gtest/gtest.h>
#include <vector>

namespace eposp::vm {
namespace {

struct Case {
    const char* type_name;
    TypeKind kind;
    Scalar scalar;
    std::vector<std::uint8_t> bytes;
    const char* text;
};

template <typename T>
std::vector<std::uint8_t> bytes_of(T value) {
    std::vector<std::uint8_t> bytes(sizeof(T));
    std::memcpy(bytes.data(), &value, sizeof(T));
    return bytes;
}

class FormatValue : public ::testing::TestWithParam<Case> {};

TEST_P(FormatValue, ShowsTheLiteral) {
    const Case& c = GetParam();
    Image image;
    TypeDescriptor type;
    type.name = c.type_name;
    type.kind = c.kind;
    type.scalar = c.scalar;
    type.size = static_cast<std::uint32_t>(c.bytes.size());
    image.types.push_back(type);
    EXPECT_EQ(format_value(image, c.bytes, VariableLocation{0, 0}), c.text);
}

constexpr std::int64_t kNsPerMs = 1'000'000;

INSTANTIATE_TEST_SUITE_P(
    Types, FormatValue,
    ::testing::Values(
        Case{"BOOL", TypeKind::Elementary, Scalar::Bool, {1}, "TRUE"},
        Case{"BOOL", TypeKind::Elementary, Scalar::Bool, {0}, "FALSE"},
        Case{"SINT", TypeKind::Elementary, Scalar::I8, bytes_of<std::int8_t>(-128), "-128"},
        Case{"DINT", TypeKind::Elementary, Scalar::I32, bytes_of(-42), "-42"},
        Case{"ULINT", TypeKind::Elementary, Scalar::U64, bytes_of(~std::uint64_t{0}),
             "18446744073709551615"},
        Case{"LREAL", TypeKind::Elementary, Scalar::F64, bytes_of(1.5), "1.5"},
        Case{"REAL", TypeKind::Elementary, Scalar::F32, bytes_of(0.1F), "0.1"},
        Case{"TIME", TypeKind::Elementary, Scalar::I64, bytes_of(1500 * kNsPerMs), "T#1s500ms"},
        Case{"LTIME", TypeKind::Elementary, Scalar::I64, bytes_of(2 * kNsPerMs), "LTIME#2ms"},
        Case{"DATE", TypeKind::Elementary, Scalar::I64,
             bytes_of(std::int64_t{86'400} * 1000 * kNsPerMs), "D#1970-01-02"},
        Case{"LDATE", TypeKind::Elementary, Scalar::I64,
             bytes_of(std::int64_t{86'400} * 1000 * kNsPerMs), "LDATE#1970-01-02"},
        Case{"TOD", TypeKind::Elementary, Scalar::I64, bytes_of(1500 * kNsPerMs), "TOD#00:00:01.5"},
        Case{"LTOD", TypeKind::Elementary, Scalar::I64, bytes_of(1500 * kNsPerMs + 7),
             "LTOD#00:00:01.500000007"},
        Case{"DT", TypeKind::Elementary, Scalar::I64, bytes_of(-kNsPerMs),
             "DT#1969-12-31-23:59:59.999"},
        Case{"LDT", TypeKind::Elementary, Scalar::I64, bytes_of(std::int64_t{1}),
             "LDT#1970-01-01-00:00:00.000000001"},
        Case{"LINT", TypeKind::Elementary, Scalar::I64, bytes_of(std::int64_t{-7}), "-7"},
        Case{"STRING[8]", TypeKind::String, Scalar::Bool, stdlib::string_image(8, "it's $5\n"),
             "'it$'s $$5$0A'"},
        Case{"CHAR", TypeKind::Elementary, Scalar::U8, {'A'}, "'A'"},
        Case{"CHAR", TypeKind::Elementary, Scalar::U8, {'\''}, "'$''"},
        Case{"CHAR", TypeKind::Elementary, Scalar::U8, {'$'}, "'$$'"},
        Case{"CHAR", TypeKind::Elementary, Scalar::U8, {'\n'}, "'$0A'"},
        Case{"CHAR", TypeKind::Elementary, Scalar::U8, {0xE9}, "'$E9'"},
        Case{"WCHAR", TypeKind::Elementary, Scalar::U16, bytes_of(std::uint16_t{'A'}), "\"A\""},
        Case{"WCHAR", TypeKind::Elementary, Scalar::U16, bytes_of(std::uint16_t{'"'}), "\"$\"\""},
        Case{"WCHAR", TypeKind::Elementary, Scalar::U16, bytes_of(std::uint16_t{0x263A}),
             "\"$263A\""},
        Case{"USINT", TypeKind::Elementary, Scalar::U8, {'A'}, "65"},
        Case{"WORD", TypeKind::Elementary, Scalar::U16, bytes_of(std::uint16_t{'A'}), "65"},
        Case{"ARRAY[1..2] OF INT",
             TypeKind::Array,
             Scalar::Bool,
             {0, 0, 0, 0},
             "<ARRAY[1..2] OF INT>"}));

// An enumeration shows the name of its value, a value it does not name as the number.
TEST(FormatValue, EnumerationsShowTheNameOfTheirValue) {
    Image image;
    TypeDescriptor step;
    step.name = "Step";
    step.scalar = Scalar::I16;
    step.size = 2;
    step.enumerators = {{"Idle", 0}, {"Back", -1}, {"Travel", 7}};
    image.types.push_back(step);
    for (const auto& [value, text] :
         {std::pair<std::int16_t, const char*>{7, "Travel"}, {-1, "Back"}, {0, "Idle"}, {3, "3"}}) {
        EXPECT_EQ(format_value(image, bytes_of(value), VariableLocation{0, 0}), text);
    }
}

} // namespace
} // namespace eposp::vm
