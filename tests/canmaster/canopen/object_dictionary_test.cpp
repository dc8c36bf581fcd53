#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"

#include <cctype>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace eposp::canopen {
namespace {

using Limit = std::optional<Bytes>;

// One remote write to a VAR object and the code CiA 301 7.2.4.3.17 wants for it.
struct WriteCase {
    const char* what;
    DataType type;
    Access access;
    Bytes default_value;
    Limit low;
    Limit high;
    Bytes data;
    AbortCode expected;
};

class ObjectDictionaryWrite : public testing::TestWithParam<WriteCase> {};

TEST_P(ObjectDictionaryWrite, ChecksAccessLengthAndRangeInThatOrder) {
    const WriteCase& c = GetParam();
    ObjectDictionary od;
    SubObject& sub = od.add_variable(0x2000, "value", c.type, c.access, c.default_value);
    sub.low_limit = c.low;
    sub.high_limit = c.high;

    EXPECT_EQ(od.write(0x2000, 0, c.data), c.expected) << c.what;
    EXPECT_EQ(od.get(0x2000, 0), c.expected == AbortCode::None ? c.data : c.default_value)
        << c.what;
}

const std::vector<WriteCase> kWriteCases = {
    {"rw accepts",
     DataType::Unsigned16,
     Access::ReadWrite,
     {0, 0},
     {},
     {},
     {1, 2},
     AbortCode::None},
    {"ro refuses",
     DataType::Unsigned16,
     Access::ReadOnly,
     {0, 0},
     {},
     {},
     {1, 2},
     AbortCode::ReadOnly},
    {"const refuses as read-only",
     DataType::Unsigned16,
     Access::Const,
     {0, 0},
     {},
     {},
     {1, 2},
     AbortCode::ReadOnly},
    {"wo accepts",
     DataType::Unsigned16,
     Access::WriteOnly,
     {0, 0},
     {},
     {},
     {1, 2},
     AbortCode::None},
    {"rwr accepts",
     DataType::Unsigned16,
     Access::ReadWriteInput,
     {0, 0},
     {},
     {},
     {1, 2},
     AbortCode::None},
    {"rww accepts",
     DataType::Unsigned16,
     Access::ReadWriteOutput,
     {0, 0},
     {},
     {},
     {1, 2},
     AbortCode::None},
    {"access is checked before length",
     DataType::Unsigned16,
     Access::ReadOnly,
     {0, 0},
     {},
     {},
     {1},
     AbortCode::ReadOnly},
    {"too short",
     DataType::Unsigned32,
     Access::ReadWrite,
     {0, 0, 0, 0},
     {},
     {},
     {1, 2, 3},
     AbortCode::LengthTooLow},
    {"too long",
     DataType::Unsigned32,
     Access::ReadWrite,
     {0, 0, 0, 0},
     {},
     {},
     {1, 2, 3, 4, 5},
     AbortCode::LengthTooHigh},
    {"empty for a fixed size",
     DataType::Unsigned8,
     Access::ReadWrite,
     {0},
     {},
     {},
     {},
     AbortCode::LengthTooLow},
    {"INTEGER24 takes three bytes",
     DataType::Integer24,
     Access::ReadWrite,
     {0, 0, 0},
     {},
     {},
     {1, 2, 3, 4},
     AbortCode::LengthTooHigh},
    {"UNSIGNED above high",
     DataType::Unsigned16,
     Access::ReadWrite,
     {10, 0},
     encode<uint16_t>(10),
     encode<uint16_t>(1000),
     encode<uint16_t>(1001),
     AbortCode::ValueTooHigh},
    {"UNSIGNED at high",
     DataType::Unsigned16,
     Access::ReadWrite,
     {10, 0},
     encode<uint16_t>(10),
     encode<uint16_t>(1000),
     encode<uint16_t>(1000),
     AbortCode::None},
    {"UNSIGNED below low",
     DataType::Unsigned16,
     Access::ReadWrite,
     {10, 0},
     encode<uint16_t>(10),
     encode<uint16_t>(1000),
     encode<uint16_t>(9),
     AbortCode::ValueTooLow},
    {"UNSIGNED32 above 2^31 compares unsigned",
     DataType::Unsigned32,
     Access::ReadWrite,
     {0, 0, 0, 0},
     {},
     encode<uint32_t>(0x8000'0000),
     encode<uint32_t>(0xFFFF'FFFF),
     AbortCode::ValueTooHigh},
    {"INTEGER16 negative below low",
     DataType::Integer16,
     Access::ReadWrite,
     {0, 0},
     encode<int16_t>(-100),
     encode<int16_t>(100),
     encode<int16_t>(-101),
     AbortCode::ValueTooLow},
    {"INTEGER16 negative in range",
     DataType::Integer16,
     Access::ReadWrite,
     {0, 0},
     encode<int16_t>(-100),
     encode<int16_t>(100),
     encode<int16_t>(-100),
     AbortCode::None},
    {"INTEGER24 is sign-extended",
     DataType::Integer24,
     Access::ReadWrite,
     {0, 0, 0},
     Bytes{0x00, 0x00, 0xF0},
     Bytes{0xFF, 0xFF, 0x0F},
     Bytes{0xFF, 0xFF, 0xEF},
     AbortCode::ValueTooLow},
    {"INTEGER64 extremes", DataType::Integer64, Access::ReadWrite, encode<int64_t>(0),
     encode<int64_t>(-5), encode<int64_t>(5), encode(std::numeric_limits<int64_t>::min()),
     AbortCode::ValueTooLow},
    {"UNSIGNED64 beyond INT64_MAX",
     DataType::Unsigned64,
     Access::ReadWrite,
     encode<uint64_t>(0),
     {},
     encode<uint64_t>(0x8000'0000'0000'0000),
     encode(std::numeric_limits<uint64_t>::max()),
     AbortCode::ValueTooHigh},
    {"REAL32 above high", DataType::Real32, Access::ReadWrite, encode(0.0F), encode(-1.5F),
     encode(1.5F), encode(1.75F), AbortCode::ValueTooHigh},
    {"REAL32 below negative low", DataType::Real32, Access::ReadWrite, encode(0.0F), encode(-1.5F),
     encode(1.5F), encode(-2.0F), AbortCode::ValueTooLow},
    {"REAL32 NaN is out of any range", DataType::Real32, Access::ReadWrite, encode(0.0F),
     encode(-1.5F), encode(1.5F), encode(std::numeric_limits<float>::quiet_NaN()),
     AbortCode::InvalidValue},
    {"REAL64 in range", DataType::Real64, Access::ReadWrite, encode(0.0), encode(-1e9), encode(1e9),
     encode(-1e8), AbortCode::None},
    {"only a high limit",
     DataType::Integer8,
     Access::ReadWrite,
     {0},
     {},
     encode<int8_t>(3),
     encode<int8_t>(-128),
     AbortCode::None},
    {"VISIBLE_STRING of any length",
     DataType::VisibleString,
     Access::ReadWrite,
     {'a'},
     {},
     {},
     Bytes(300, 'x'),
     AbortCode::None},
    {"empty VISIBLE_STRING",
     DataType::VisibleString,
     Access::ReadWrite,
     {'a'},
     {},
     {},
     Bytes{},
     AbortCode::None},
    {"DOMAIN of 64 KiB",
     DataType::Domain,
     Access::ReadWrite,
     {},
     {},
     {},
     Bytes(65536, 7),
     AbortCode::None},
    {"DOMAIN above the maximum",
     DataType::Domain,
     Access::ReadWrite,
     {},
     {},
     {},
     Bytes(SubObject::kDefaultMaxLength + 1, 7),
     AbortCode::LengthTooHigh},
    {"read-only string",
     DataType::VisibleString,
     Access::Const,
     {'a'},
     {},
     {},
     {'b'},
     AbortCode::ReadOnly},
};

// "UNSIGNED above high" -> UNSIGNED_above_high, so ctest lists the case by what it checks.
std::string test_name(std::string_view what) {
    std::string name;
    for (const char c : what) {
        name += std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
    }
    return name;
}

INSTANTIATE_TEST_SUITE_P(Table, ObjectDictionaryWrite, testing::ValuesIn(kWriteCases),
                         [](const auto& param_info) { return test_name(param_info.param.what); });

struct ReadCase {
    Access access;
    AbortCode expected;
};

class ObjectDictionaryRead : public testing::TestWithParam<ReadCase> {};

TEST_P(ObjectDictionaryRead, RefusesOnlyWriteOnlyObjects) {
    ObjectDictionary od;
    od.add_variable(0x2000, "value", DataType::Unsigned8, GetParam().access, {42});
    Bytes out;
    EXPECT_EQ(od.read(0x2000, 0, out), GetParam().expected);
    EXPECT_EQ(out, GetParam().expected == AbortCode::None ? Bytes{42} : Bytes{});
}

INSTANTIATE_TEST_SUITE_P(Table, ObjectDictionaryRead,
                         testing::Values(ReadCase{Access::Const, AbortCode::None},
                                         ReadCase{Access::ReadOnly, AbortCode::None},
                                         ReadCase{Access::WriteOnly, AbortCode::WriteOnly},
                                         ReadCase{Access::ReadWrite, AbortCode::None},
                                         ReadCase{Access::ReadWriteInput, AbortCode::None},
                                         ReadCase{Access::ReadWriteOutput, AbortCode::None}),
                         [](const auto& param_info) {
                             return test_name(to_string(param_info.param.access));
                         });

ObjectDictionary dictionary_with_a_record() {
    ObjectDictionary od;
    od.add_variable(0x1000, "Device type", DataType::Unsigned32, Access::ReadOnly,
                    encode<uint32_t>(0x20192));
    od.add_object(0x1018, "Identity", ObjectCode::Record);
    od.add_sub(0x1018, 1, "Vendor-ID", DataType::Unsigned32, Access::ReadOnly,
               encode<uint32_t>(0xFB));
    return od;
}

TEST(ObjectDictionary, MissingIndexAndMissingSubIndexHaveTheirOwnCodes) {
    ObjectDictionary od = dictionary_with_a_record();
    Bytes out;
    const Bytes data{1, 0, 0, 0};
    EXPECT_EQ(od.read(0x1001, 0, out), AbortCode::ObjectDoesNotExist);
    EXPECT_EQ(od.write(0x1001, 0, data), AbortCode::ObjectDoesNotExist);
    EXPECT_EQ(od.read(0x1018, 2, out), AbortCode::SubIndexDoesNotExist);
    EXPECT_EQ(od.write(0x1018, 2, data), AbortCode::SubIndexDoesNotExist);
    EXPECT_EQ(od.read(0x1000, 1, out), AbortCode::SubIndexDoesNotExist);
    EXPECT_EQ(od.check_write_size(0x1001, 0, 4), AbortCode::ObjectDoesNotExist);
    EXPECT_EQ(od.check_write_size(0x1018, 2, 4), AbortCode::SubIndexDoesNotExist);
}

TEST(ObjectDictionary, CheckWriteSizeRefusesBeforeTheDataArrives) {
    ObjectDictionary od;
    od.add_variable(0x2000, "u32", DataType::Unsigned32, Access::ReadWrite, {0, 0, 0, 0});
    od.add_variable(0x2001, "text", DataType::VisibleString, Access::ReadWrite, {});
    od.find(0x2001, 0)->max_length = 10;
    EXPECT_EQ(od.check_write_size(0x2000, 0, 4), AbortCode::None);
    EXPECT_EQ(od.check_write_size(0x2000, 0, 8), AbortCode::LengthTooHigh);
    EXPECT_EQ(od.check_write_size(0x2001, 0, 10), AbortCode::None);
    EXPECT_EQ(od.check_write_size(0x2001, 0, 11), AbortCode::LengthTooHigh);
}

TEST(ObjectDictionary, SubIndexZeroHoldsTheHighestSubIndexAndIsReadOnly) {
    ObjectDictionary od;
    od.add_object(0x1600, "RPDO mapping", ObjectCode::Array);
    EXPECT_EQ(od.get_as<uint8_t>(0x1600, 0), 0);
    od.add_sub(0x1600, 3, "third", DataType::Unsigned32, Access::ReadWrite, {0, 0, 0, 0});
    od.add_sub(0x1600, 1, "first", DataType::Unsigned32, Access::ReadWrite, {0, 0, 0, 0});
    EXPECT_EQ(od.get_as<uint8_t>(0x1600, 0), 3);
    EXPECT_EQ(od.find(0x1600, 0)->default_value, Bytes{3});
    EXPECT_EQ(od.find(0x1600, 0)->type, DataType::Unsigned8);
    EXPECT_EQ(od.write(0x1600, 0, Bytes{1}), AbortCode::ReadOnly);
    EXPECT_EQ(od.find(0x1600)->code, ObjectCode::Array);
}

TEST(ObjectDictionary, WriteHookRefusesWithItsCodeAndLeavesTheValue) {
    ObjectDictionary od;
    SubObject& sub =
        od.add_variable(0x1800, "COB-ID", DataType::Unsigned32, Access::ReadWrite, {0, 0, 0, 0});
    std::vector<Bytes> seen;
    sub.on_write = [&](std::span<const std::uint8_t> value) {
        seen.emplace_back(value.begin(), value.end());
        return value[0] == 0xFF ? AbortCode::InvalidValue : AbortCode::None;
    };
    int changes = 0;
    od.on_change(0x1800, [&](auto, auto) { ++changes; });

    EXPECT_EQ(od.write(0x1800, 0, Bytes{0xFF, 0, 0, 0}), AbortCode::InvalidValue);
    EXPECT_EQ(od.get(0x1800, 0), (Bytes{0, 0, 0, 0}));
    EXPECT_EQ(changes, 0);
    EXPECT_EQ(od.write(0x1800, 0, Bytes{0x01, 0, 0, 0}), AbortCode::None);
    EXPECT_EQ(od.get(0x1800, 0), (Bytes{1, 0, 0, 0}));
    EXPECT_EQ(changes, 1);
    EXPECT_EQ(seen.size(), 2U);
}

TEST(ObjectDictionary, WriteHookIsNotCalledForARefusedLengthOrRange) {
    ObjectDictionary od;
    SubObject& sub = od.add_variable(0x2000, "v", DataType::Unsigned8, Access::ReadWrite, {0});
    sub.high_limit = Bytes{10};
    int calls = 0;
    sub.on_write = [&](auto) {
        ++calls;
        return AbortCode::None;
    };
    EXPECT_EQ(od.write(0x2000, 0, Bytes{1, 2}), AbortCode::LengthTooHigh);
    EXPECT_EQ(od.write(0x2000, 0, Bytes{11}), AbortCode::ValueTooHigh);
    EXPECT_EQ(calls, 0);
}

TEST(ObjectDictionary, ListenersSeeTheStoredValueAfterWriteAndSet) {
    ObjectDictionary od = dictionary_with_a_record();
    od.add_sub(0x1018, 2, "Product code", DataType::Unsigned32, Access::ReadWrite, {0, 0, 0, 0});
    std::vector<std::pair<std::uint16_t, std::uint8_t>> calls;
    std::vector<std::uint32_t> values;
    od.on_change(0x1018, [&](std::uint16_t index, std::uint8_t sub_index) {
        calls.emplace_back(index, sub_index);
        values.push_back(od.get_as<std::uint32_t>(index, sub_index));
    });
    int other = 0;
    od.on_change(0x1000, [&](auto, auto) { ++other; });

    EXPECT_EQ(od.write(0x1018, 2, encode<uint32_t>(7)), AbortCode::None);
    od.set_as<std::uint32_t>(0x1018, 1, 9);
    EXPECT_EQ(od.write(0x1018, 1, encode<uint32_t>(1)), AbortCode::ReadOnly);

    EXPECT_EQ(calls,
              (std::vector<std::pair<std::uint16_t, std::uint8_t>>{{0x1018, 2}, {0x1018, 1}}));
    EXPECT_EQ(values, (std::vector<std::uint32_t>{7, 9}));
    EXPECT_EQ(other, 0);
}

TEST(ObjectDictionary, RemovedListenersAreNotCalledEvenDuringANotification) {
    ObjectDictionary od;
    od.add_variable(0x2000, "v", DataType::Unsigned8, Access::ReadWrite, {0});
    int first = 0;
    int second = 0;
    ObjectDictionary::ListenerId second_id = 0;
    od.on_change(0x2000, [&](auto, auto) {
        ++first;
        od.remove_listener(second_id);
    });
    second_id = od.on_change(0x2000, [&](auto, auto) { ++second; });
    od.set_as<std::uint8_t>(0x2000, 0, 1);
    EXPECT_EQ(first, 1);
    EXPECT_EQ(second, 0);
}

TEST(ObjectDictionary, ReadHookComputesTheValue) {
    ObjectDictionary od;
    SubObject& sub =
        od.add_variable(0x1001, "Error register", DataType::Unsigned8, Access::ReadOnly, {0});
    std::uint8_t error_register = 0x11;
    sub.on_read = [&] {
        return Bytes{error_register};
    };
    Bytes out;
    EXPECT_EQ(od.read(0x1001, 0, out), AbortCode::None);
    EXPECT_EQ(out, Bytes{0x11});
    error_register = 0x01;
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1001, 0), 0x01);
}

TEST(ObjectDictionary, ResetToDefaultsRestoresEveryValueWithoutTellingListeners) {
    ObjectDictionary od = dictionary_with_a_record();
    od.add_variable(0x2000, "v", DataType::Integer32, Access::ReadWrite, encode<int32_t>(-3));
    od.set_as<std::int32_t>(0x2000, 0, 100);
    od.set_as<std::uint32_t>(0x1018, 1, 5);
    int changes = 0;
    od.on_change(0x2000, [&](auto, auto) { ++changes; });
    od.reset_to_defaults();
    EXPECT_EQ(od.get_as<std::int32_t>(0x2000, 0), -3);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1018, 1), 0xFBU);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1018, 0), 1);
    EXPECT_EQ(changes, 0);
}

TEST(ObjectDictionary, SetChecksOnlyTheType) {
    ObjectDictionary od = dictionary_with_a_record();
    od.set_as<std::uint32_t>(0x1000, 0, 1); // read-only for a remote client, not for the device
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1000, 0), 1U);
    EXPECT_THROW(od.set(0x1000, 0, Bytes{1, 2}), std::invalid_argument);
}

// find() reads a table of pages of 256 indices: indices at the edges of a page, in pages of
// their own and missing ones next to present ones, in the dictionary, its copy and its move.
TEST(ObjectDictionary, FindsEveryObjectByIndexAfterCopyAndMove) {
    const std::vector<std::uint16_t> present{0x0000, 0x00FF, 0x1000, 0x10FF,
                                             0x1100, 0x6041, 0xFFFF};
    const std::vector<std::uint16_t> missing{0x0001, 0x0100, 0x1001, 0x10FE,
                                             0x6040, 0x7000, 0xFFFE};
    ObjectDictionary od;
    for (const std::uint16_t index : present) {
        const auto value = encode_array(index);
        od.add_variable(index, "value", DataType::Unsigned16, Access::ReadWrite,
                        Bytes(value.begin(), value.end()));
    }
    const auto expect_finds = [&](ObjectDictionary& dictionary) {
        for (const std::uint16_t index : present) {
            const Object* object = dictionary.find(index);
            ASSERT_NE(object, nullptr) << index;
            EXPECT_EQ(object->index, index);
            EXPECT_EQ(object, &dictionary.objects().at(index)); // its own, not the original's
            EXPECT_EQ(dictionary.get_as<std::uint16_t>(index, 0), index);
        }
        for (const std::uint16_t index : missing) {
            EXPECT_EQ(dictionary.find(index), nullptr) << index;
            EXPECT_EQ(dictionary.find(index, 0), nullptr) << index;
        }
    };
    expect_finds(od);
    ObjectDictionary copy(od);
    expect_finds(copy);
    ObjectDictionary assigned;
    assigned.add_variable(0x1001, "gone after the assignment", DataType::Unsigned8,
                          Access::ReadWrite, {0});
    assigned = od;
    expect_finds(assigned);
    ObjectDictionary moved(std::move(copy));
    expect_finds(moved);
    ObjectDictionary move_assigned;
    move_assigned = std::move(assigned);
    expect_finds(move_assigned);
    od.add_variable(0x6040, "added later", DataType::Unsigned16, Access::ReadWrite, {0, 0});
    EXPECT_NE(od.find(0x6040), nullptr);
    EXPECT_EQ(moved.find(0x6040), nullptr);
}

TEST(ObjectDictionary, MisuseIsAProgrammingError) {
    ObjectDictionary od = dictionary_with_a_record();
    EXPECT_THROW(od.add_variable(0x1000, "again", DataType::Unsigned8, Access::ReadOnly, {0}),
                 std::invalid_argument);
    EXPECT_THROW(od.add_variable(0x2000, "short", DataType::Unsigned16, Access::ReadOnly, {0}),
                 std::invalid_argument);
    EXPECT_THROW(od.add_object(0x1018, "again", ObjectCode::Record), std::invalid_argument);
    EXPECT_THROW(od.add_object(0x2001, "var", ObjectCode::Var), std::invalid_argument);
    EXPECT_THROW(od.add_sub(0x1000, 1, "of a VAR", DataType::Unsigned8, Access::ReadOnly, {0}),
                 std::invalid_argument);
    EXPECT_THROW(
        od.add_sub(0x1018, 1, "twice", DataType::Unsigned32, Access::ReadOnly, {0, 0, 0, 0}),
        std::invalid_argument);
    EXPECT_THROW(od.add_sub(0x1018, 0, "sub 0", DataType::Unsigned8, Access::ReadOnly, {0}),
                 std::invalid_argument);
    EXPECT_THROW((void)od.get(0x3000, 0), std::out_of_range);
    EXPECT_THROW(od.set(0x3000, 0, Bytes{0}), std::out_of_range);
}

// A value looked up once is stored as set() by index stores it: the listeners hear the index and
// sub-index, a wrong length is refused; the reference outlives a move of the dictionary.
TEST(ObjectDictionary, SetThroughAValueRefActsAsSetByIndex) {
    ObjectDictionary od;
    od.add_object(0x2071, "Digital Input Functionalities", ObjectCode::Record);
    od.add_sub(0x2071, 1, "State", DataType::Unsigned16, Access::ReadOnly,
               encode(std::uint16_t{0}));
    EXPECT_THROW((void)od.value_ref(0x2071, 2), std::out_of_range);
    EXPECT_THROW((void)od.value_ref(0x2072, 0), std::out_of_range);
    const ValueRef state = od.value_ref(0x2071, 1);
    ObjectDictionary moved = std::move(od);
    std::vector<std::pair<std::uint16_t, std::uint8_t>> heard;
    moved.on_change(0x2071, [&heard](std::uint16_t index, std::uint8_t sub_index) {
        heard.emplace_back(index, sub_index);
    });
    moved.set_as(state, std::uint16_t{0x1234});
    EXPECT_EQ(moved.get_as<std::uint16_t>(0x2071, 1), 0x1234);
    EXPECT_EQ(heard, (std::vector<std::pair<std::uint16_t, std::uint8_t>>{{0x2071, 1}}));
    EXPECT_THROW(moved.set_as(state, std::uint32_t{1}), std::invalid_argument);
    EXPECT_EQ(moved.get_as<std::uint16_t>(0x2071, 1), 0x1234);
}

TEST(ObjectDictionary, AccessNamesAndRightsFollowCia306) {
    struct Row {
        Access access;
        std::string_view name;
        bool readable;
        bool writable;
    };
    for (const Row& row :
         {Row{Access::Const, "const", true, false}, Row{Access::ReadOnly, "ro", true, false},
          Row{Access::WriteOnly, "wo", false, true}, Row{Access::ReadWrite, "rw", true, true},
          Row{Access::ReadWriteInput, "rwr", true, true},
          Row{Access::ReadWriteOutput, "rww", true, true}}) {
        EXPECT_EQ(to_string(row.access), row.name);
        EXPECT_EQ(readable(row.access), row.readable) << row.name;
        EXPECT_EQ(writable(row.access), row.writable) << row.name;
    }
}

// CiA 301 7.4.7.1 (table 44) and 7.1.
TEST(DataType, SizesNamesAndClassesFollowCia301) {
    struct Row {
        DataType type;
        std::string_view name;
        std::optional<std::size_t> size;
        std::optional<std::size_t> bits;
        char kind; // s signed, u unsigned, r real, b boolean, - other
    };
    const std::vector<Row> rows = {
        {DataType::Boolean, "BOOLEAN", 1, 1, 'b'},
        {DataType::Integer8, "INTEGER8", 1, 8, 's'},
        {DataType::Integer16, "INTEGER16", 2, 16, 's'},
        {DataType::Integer24, "INTEGER24", 3, 24, 's'},
        {DataType::Integer32, "INTEGER32", 4, 32, 's'},
        {DataType::Integer40, "INTEGER40", 5, 40, 's'},
        {DataType::Integer48, "INTEGER48", 6, 48, 's'},
        {DataType::Integer56, "INTEGER56", 7, 56, 's'},
        {DataType::Integer64, "INTEGER64", 8, 64, 's'},
        {DataType::Unsigned8, "UNSIGNED8", 1, 8, 'u'},
        {DataType::Unsigned16, "UNSIGNED16", 2, 16, 'u'},
        {DataType::Unsigned24, "UNSIGNED24", 3, 24, 'u'},
        {DataType::Unsigned32, "UNSIGNED32", 4, 32, 'u'},
        {DataType::Unsigned40, "UNSIGNED40", 5, 40, 'u'},
        {DataType::Unsigned48, "UNSIGNED48", 6, 48, 'u'},
        {DataType::Unsigned56, "UNSIGNED56", 7, 56, 'u'},
        {DataType::Unsigned64, "UNSIGNED64", 8, 64, 'u'},
        {DataType::Real32, "REAL32", 4, 32, 'r'},
        {DataType::Real64, "REAL64", 8, 64, 'r'},
        {DataType::TimeOfDay, "TIME_OF_DAY", 6, 48, '-'},
        {DataType::TimeDifference, "TIME_DIFFERENCE", 6, 48, '-'},
        {DataType::VisibleString, "VISIBLE_STRING", {}, {}, '-'},
        {DataType::OctetString, "OCTET_STRING", {}, {}, '-'},
        {DataType::UnicodeString, "UNICODE_STRING", {}, {}, '-'},
        {DataType::Domain, "DOMAIN", {}, {}, '-'},
    };
    for (const Row& row : rows) {
        EXPECT_EQ(to_string(row.type), row.name);
        EXPECT_EQ(fixed_size(row.type), row.size) << row.name;
        EXPECT_EQ(mapping_bits(row.type), row.bits) << row.name;
        EXPECT_EQ(is_signed_integer(row.type), row.kind == 's') << row.name;
        EXPECT_EQ(is_unsigned_integer(row.type), row.kind == 'u') << row.name;
        EXPECT_EQ(is_real(row.type), row.kind == 'r') << row.name;
        EXPECT_EQ(is_numeric(row.type), row.kind != '-') << row.name;
        EXPECT_EQ(data_type_from_index(static_cast<std::uint16_t>(row.type)), row.type);
    }
    EXPECT_EQ(data_type_from_index(0x000E), std::nullopt);
    EXPECT_EQ(data_type_from_index(0x0017), std::nullopt);
    EXPECT_EQ(data_type_from_index(0x0020), std::nullopt);
}

// EPOS2 firmware specification 4.3, table 4-12: every code with its name.
TEST(AbortCode, DescribeGivesTheNamesOfEpos2Table4_12) {
    struct Row {
        std::uint32_t code;
        std::string_view name;
    };
    const std::vector<Row> rows = {
        {0x0000'0000, "No Communication Error"},
        {0x0503'0000, "Toggle Error"},
        {0x0504'0000, "SDO Time Out"},
        {0x0504'0001, "Client / Server Specifier Error"},
        {0x0504'0005, "Out of Memory Error"},
        {0x0601'0000, "Access Error"},
        {0x0601'0001, "Write Only"},
        {0x0601'0002, "Read Only"},
        {0x0602'0000, "Object does not exist Error"},
        {0x0604'0041, "PDO mapping Error"},
        {0x0604'0042, "PDO Length Error"},
        {0x0604'0043, "General Parameter Error"},
        {0x0604'0047, "General internal Incompatibility Error"},
        {0x0606'0000, "Hardware Error"},
        {0x0607'0010, "Service Parameter Error"},
        {0x0607'0012, "Service Parameter too long Error"},
        {0x0607'0013, "Service Parameter too short Error"},
        {0x0609'0011, "Object Subindex Error"},
        {0x0609'0030, "Value Range Error"},
        {0x0609'0031, "Value too high Error"},
        {0x0609'0032, "Value too low Error"},
        {0x0609'0036, "Maximum less Minimum Error"},
        {0x0800'0000, "General Error"},
        {0x0800'0020, "Transfer or store Error"},
        {0x0800'0021, "Local Control Error"},
        {0x0800'0022, "Wrong Device State"},
        {0x0F00'FFC0, "Wrong NMT State Error"},
        {0x0F00'FFBF, "Illegal Command Error"},
        {0x0F00'FFBE, "Password Error"},
        {0x0F00'FFBC, "Error Service Mode"},
        {0x0F00'FFB9, "Error CAN ID"},
    };
    for (const Row& row : rows) {
        EXPECT_EQ(describe(static_cast<AbortCode>(row.code)), row.name) << std::hex << row.code;
    }
}

TEST(AbortCode, CodesOutsideTable4_12UseCia301Wording) {
    EXPECT_EQ(describe(AbortCode::InvalidBlockSize), "Invalid block size");
    EXPECT_EQ(describe(AbortCode::InvalidSequenceNumber), "Invalid sequence number");
    EXPECT_EQ(describe(AbortCode::CrcError), "CRC error");
    EXPECT_EQ(describe(AbortCode::ResourceNotAvailable), "Resource not available: SDO connection");
    EXPECT_EQ(describe(AbortCode::NoDataAvailable), "No data available");
    EXPECT_EQ(describe(static_cast<AbortCode>(0x1234'5678)), "Unknown abort code");
}

TEST(NmtState, NamesFollowCia301) {
    EXPECT_EQ(to_string(NmtState::Initialising), "Initialising");
    EXPECT_EQ(to_string(NmtState::Stopped), "Stopped");
    EXPECT_EQ(to_string(NmtState::Operational), "Operational");
    EXPECT_EQ(to_string(NmtState::PreOperational), "Pre-operational");
    EXPECT_EQ(to_string(static_cast<NmtState>(0x42)), "unknown");
}

} // namespace
} // namespace eposp::canopen
