// The EPOS P dictionary against chapter 10 of its firmware specification, and its EDS.
#include "eposp/canopen/eds_import.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/test/same_dictionary.hpp"
#include "eposp/test/test_directory.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

namespace eposp::device {
namespace {

using canopen::AbortCode;
using canopen::Access;
using canopen::DataType;
using canopen::ObjectCode;

struct ListedObject {
    std::uint16_t first;
    std::uint16_t last;
    ObjectCode code;
    DataType type; ///< of sub-index 0 (VAR) or of the entries from sub-index 1 on
    Access access;
};

// Table 32, with the types and access of the sections where the table is vague ("ARRAY",
// "RECORD"). Records of mixed types list their sub-index 1.
const std::vector<ListedObject> kTable32 = {
    {0x1000, 0x1000, ObjectCode::Var, DataType::Unsigned32, Access::ReadOnly},
    {0x1001, 0x1001, ObjectCode::Var, DataType::Unsigned8, Access::ReadOnly},
    {0x1002, 0x1002, ObjectCode::Var, DataType::Unsigned32, Access::ReadOnly},
    {0x1003, 0x1003, ObjectCode::Array, DataType::Unsigned32, Access::ReadOnly},
    {0x1005, 0x1005, ObjectCode::Var, DataType::Unsigned32, Access::ReadWrite},
    {0x1006, 0x1006, ObjectCode::Var, DataType::Unsigned32, Access::ReadWrite},
    {0x1007, 0x1007, ObjectCode::Var, DataType::Unsigned32, Access::ReadWrite},
    {0x1008, 0x1008, ObjectCode::Var, DataType::VisibleString, Access::Const},
    {0x1010, 0x1010, ObjectCode::Array, DataType::Unsigned32, Access::ReadWrite},
    {0x1011, 0x1011, ObjectCode::Array, DataType::Unsigned32, Access::ReadWrite},
    {0x1016, 0x1016, ObjectCode::Array, DataType::Unsigned32, Access::ReadWrite},
    {0x1017, 0x1017, ObjectCode::Var, DataType::Unsigned16, Access::ReadWrite},
    {0x1018, 0x1018, ObjectCode::Record, DataType::Unsigned32, Access::ReadOnly},
    {0x1019, 0x1019, ObjectCode::Var, DataType::Unsigned8, Access::ReadWrite},
    {0x1280, 0x12FF, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1400, 0x141F, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1500, 0x1503, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1600, 0x161F, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1700, 0x1703, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1800, 0x181F, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1900, 0x1903, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1A00, 0x1A1F, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1B00, 0x1B03, ObjectCode::Record, DataType::Unsigned32, Access::ReadWrite},
    {0x1F26, 0x1F27, ObjectCode::Array, DataType::Unsigned32, Access::ReadWrite},
    {0x1F80, 0x1F80, ObjectCode::Var, DataType::Unsigned32, Access::ReadWrite},
    {0x1F81, 0x1F82, ObjectCode::Array, DataType::Unsigned32, Access::ReadWrite},
    {0x1F84, 0x1F88, ObjectCode::Array, DataType::Unsigned32, Access::ReadWrite},
    {0x1F89, 0x1F89, ObjectCode::Var, DataType::Unsigned32, Access::ReadWrite},
    // Beyond table 32: CiA 302-3 program download (docs/service-interface.md).
    {0x1F50, 0x1F50, ObjectCode::Array, DataType::Domain, Access::ReadWrite},
    {0x1F51, 0x1F51, ObjectCode::Array, DataType::Unsigned8, Access::ReadWrite},
    {0x1F56, 0x1F57, ObjectCode::Array, DataType::Unsigned32, Access::ReadOnly},
    {0x5000, 0x5000, ObjectCode::Var, DataType::Unsigned8, Access::ReadWrite},
    {0x5001, 0x5001, ObjectCode::Var, DataType::Unsigned16, Access::ReadWrite},
    {0x5003, 0x5004, ObjectCode::Array, DataType::Unsigned16, Access::ReadOnly},
    {0x5005, 0x5005, ObjectCode::Var, DataType::Unsigned16, Access::ReadWrite},
    {0x5280, 0x529F, ObjectCode::Record, DataType::Unsigned8, Access::ReadWrite},
    {0x5F51, 0x5F51, ObjectCode::Var, DataType::Unsigned16, Access::ReadWrite},
    // Beyond table 32: eposp's variable access (docs/service-interface.md).
    {0x5F60, 0x5F60, ObjectCode::Record, DataType::VisibleString, Access::ReadWrite},
    {0xA000, 0xA000, ObjectCode::Array, DataType::Integer8, Access::ReadWrite},
    {0xA040, 0xA040, ObjectCode::Array, DataType::Unsigned8, Access::ReadWrite},
    {0xA0C0, 0xA0C0, ObjectCode::Array, DataType::Integer16, Access::ReadWrite},
    {0xA100, 0xA100, ObjectCode::Array, DataType::Unsigned16, Access::ReadWrite},
    {0xA1C0, 0xA1C0, ObjectCode::Array, DataType::Integer32, Access::ReadWrite},
    {0xA200, 0xA200, ObjectCode::Array, DataType::Unsigned32, Access::ReadWrite},
    {0xA400, 0xA400, ObjectCode::Array, DataType::Integer8, Access::ReadWrite},
    {0xA4C0, 0xA4C0, ObjectCode::Array, DataType::Unsigned8, Access::ReadWrite},
    {0xA540, 0xA540, ObjectCode::Array, DataType::Integer16, Access::ReadWrite},
    {0xA580, 0xA580, ObjectCode::Array, DataType::Unsigned16, Access::ReadWrite},
    {0xA640, 0xA640, ObjectCode::Array, DataType::Integer32, Access::ReadWrite},
    {0xA680, 0xA680, ObjectCode::Array, DataType::Unsigned32, Access::ReadWrite},
};

/// A dictionary in the test's own directory, so that a save never touches another test's file.
class EposPDictionaryTest : public ::testing::Test {
protected:
    EposPDictionaryConfig config() const {
        EposPDictionaryConfig config;
        config.node_id = 3;
        config.serial_number = 0x1234'5678;
        config.parameter_file = directory_ / "parameters.bin";
        return config;
    }

    std::filesystem::path directory_ = test::test_directory();
};

std::uint32_t u32(const canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub) {
    return od.get_as<std::uint32_t>(index, sub);
}

AbortCode write_u32(canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub,
                    std::uint32_t value) {
    return od.write(index, sub, canopen::encode(value));
}

TEST_F(EposPDictionaryTest, HoldsEveryObjectOfTable32AndTheProgramObjectsAndNothingElse) {
    const EposPDictionary dictionary(config());
    std::size_t listed = 0;
    for (const ListedObject& row : kTable32) {
        for (std::uint32_t index = row.first; index <= row.last; ++index) {
            SCOPED_TRACE(fmt::format("0x{:04X}", index));
            ++listed;
            const canopen::Object* object =
                dictionary.objects().find(static_cast<std::uint16_t>(index));
            ASSERT_NE(object, nullptr);
            EXPECT_EQ(object->code, row.code);
            const canopen::SubObject& first = object->subs.at(row.code == ObjectCode::Var ? 0 : 1);
            EXPECT_EQ(first.type, row.type);
            EXPECT_EQ(first.access, row.access);
        }
    }
    EXPECT_EQ(dictionary.objects().objects().size(), listed);
}

TEST_F(EposPDictionaryTest, DefaultsAreTheSpecifications) {
    const EposPDictionary dictionary(config());
    const canopen::ObjectDictionary& od = dictionary.objects();
    EXPECT_EQ(u32(od, 0x1000, 0), 0x0000'0195u); // 10.1
    EXPECT_EQ(u32(od, 0x1005, 0), 0x80u);        // 10.5
    EXPECT_EQ(u32(od, 0x1006, 0), 0u);           // 10.6
    EXPECT_EQ(u32(od, 0x1007, 0), 0u);           // 10.7
    const canopen::Bytes name = od.get(0x1008, 0);
    EXPECT_EQ(std::string(name.begin(), name.end()), "EPOS P");
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1003, 0), 0u); // 10.4: no errors; room for 16
    EXPECT_NE(od.find(0x1003, 16), nullptr);
    EXPECT_EQ(od.find(0x1003, 17), nullptr);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1011, 0), 2u); // 10.10: two entries
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1016, 0), 0x80u);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x1017, 0), 0u);
    EXPECT_EQ(u32(od, 0x1018, 1), 0xFBu);
    EXPECT_EQ(u32(od, 0x1018, 2), 0x7300'0000u);
    EXPECT_EQ(u32(od, 0x1018, 3), 0x0110'0000u);
    EXPECT_EQ(u32(od, 0x1018, 4), 0x1234'5678u);
    // 10.15: 0x1280 the internal EPOS2, 0x1281 + n - 1 node n on port 2.
    EXPECT_EQ(u32(od, 0x1280, 1), 0x601u);
    EXPECT_EQ(u32(od, 0x1280, 2), 0x581u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1280, 3), 1u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1281, 3), 1u);
    EXPECT_EQ(u32(od, 0x1282, 1), 0x602u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x12FF, 3), 0x7Fu);
    EXPECT_EQ(u32(od, 0x12FF, 2), 0x5FFu);
    // 10.16 - 10.19.
    EXPECT_EQ(u32(od, 0x1400, 1), 0xC000'0000u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1400, 2), 255u);
    EXPECT_EQ(u32(od, 0x1500, 1), 0x181u);
    EXPECT_EQ(u32(od, 0x1501, 1), 0xC000'0000u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1700, 0), 1u);
    EXPECT_EQ(u32(od, 0x1700, 1), 0x5280'0210u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1600, 0), 0u);
    EXPECT_EQ(u32(od, 0x1800, 1), 0xC000'0000u);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x1800, 3), 10u);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x1903, 5), 0u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x1B03, 0), 0u);
    // 10.20 - 10.30.
    EXPECT_EQ(u32(od, 0x1F80, 0), 7u);
    EXPECT_EQ(u32(od, 0x1F81, 0x80), 0u);
    EXPECT_EQ(u32(od, 0x1F89, 0), 500u);
    // 10.31 - 10.37.
    EXPECT_EQ(od.get_as<std::uint8_t>(0x5000, 0), 3u);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x5001, 0), 0u);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x5003, 1), 0x0110u);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x5003, 2), 0x7300u);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x5005, 0), 500u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x5280, 1), kInternalSlave);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x5281, 1), kNoSlave);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x529F, 0), 3u);
    EXPECT_EQ(od.get_as<std::uint16_t>(0x5F51, 0), 0u); // 0101h: stopped by default
    EXPECT_EQ(od.get_as<std::uint8_t>(0xA000, 0), 16u);
}

TEST_F(EposPDictionaryTest, WritesOutsideTheDocumentedRangesAreRefused) {
    EposPDictionary dictionary(config());
    canopen::ObjectDictionary& od = dictionary.objects();
    EXPECT_EQ(write_u32(od, 0x1006, 0, 999), AbortCode::ValueTooLow); // 10.6: 1000..
    EXPECT_EQ(write_u32(od, 0x1006, 0, 1000), AbortCode::None);
    EXPECT_EQ(write_u32(od, 0x1006, 0, 0), AbortCode::None);          // 0: no SYNC
    EXPECT_EQ(write_u32(od, 0x1007, 0, 499), AbortCode::ValueTooLow); // 10.7: 500..
    EXPECT_EQ(write_u32(od, 0x1007, 0, 500), AbortCode::None);
    EXPECT_EQ(od.write(0x1019, 0, canopen::encode(std::uint8_t{1})), AbortCode::InvalidValue);
    EXPECT_EQ(od.write(0x1019, 0, canopen::encode(std::uint8_t{2})), AbortCode::None);
    EXPECT_EQ(write_u32(od, 0x1F89, 0, 199), AbortCode::ValueTooLow); // 10.30: 200..30000
    EXPECT_EQ(write_u32(od, 0x1F89, 0, 30001), AbortCode::ValueTooHigh);
    EXPECT_EQ(od.write(0x5001, 0, canopen::encode(std::uint16_t{5})), AbortCode::InvalidValue);
    EXPECT_EQ(od.write(0x5001, 0, canopen::encode(std::uint16_t{9})), AbortCode::None);
    EXPECT_EQ(od.write(0x5F51, 0, canopen::encode(std::uint16_t{4})), AbortCode::InvalidValue);
    EXPECT_EQ(od.write(0x5000, 0, canopen::encode(std::uint8_t{0})), AbortCode::ValueTooLow);
    // Tables 15 and 20: RPDOs 1 or 255, TPDOs 1, 253 or 255.
    EXPECT_EQ(od.write(0x1400, 2, canopen::encode(std::uint8_t{2})), AbortCode::InvalidValue);
    EXPECT_EQ(od.write(0x1400, 2, canopen::encode(std::uint8_t{1})), AbortCode::None);
    EXPECT_EQ(od.write(0x1800, 2, canopen::encode(std::uint8_t{254})), AbortCode::InvalidValue);
    EXPECT_EQ(od.write(0x1800, 2, canopen::encode(std::uint8_t{253})), AbortCode::None);
    // Tables 14 and 19: a valid PDO's CAN-ID lies in 0x181..0x57F.
    EXPECT_EQ(write_u32(od, 0x1400, 1, 0x0000'0600), AbortCode::InvalidValue);
    EXPECT_EQ(write_u32(od, 0x1400, 1, 0x0000'0201), AbortCode::None);
    // 10.15: the server's node-ID is not changeable.
    EXPECT_EQ(od.write(0x1282, 3, canopen::encode(std::uint8_t{5})), AbortCode::ValueTooHigh);
    EXPECT_EQ(od.write(0x1008, 0, canopen::encode_string("X")), AbortCode::ReadOnly);
    EXPECT_EQ(write_u32(od, 0x1000, 0, 0), AbortCode::ReadOnly);
    // 10.4: writing 0 empties the history, nothing else.
    EXPECT_EQ(od.write(0x1003, 0, canopen::encode(std::uint8_t{1})), AbortCode::InvalidValue);
    EXPECT_EQ(od.write(0x1003, 0, canopen::encode(std::uint8_t{0})), AbortCode::None);
}

TEST_F(EposPDictionaryTest, EraseSignatureCallsTheDeviceAndOthersAreRefused) {
    int erased = 0;
    EposPDictionaryConfig erasing = config();
    erasing.erase_program = [&erased] {
        ++erased;
        return AbortCode::None;
    };
    EposPDictionary dictionary(std::move(erasing));
    canopen::ObjectDictionary& od = dictionary.objects();
    EXPECT_EQ(write_u32(od, 0x1011, 2, canopen::kLoadSignature), AbortCode::TransferOrStore);
    EXPECT_EQ(erased, 0);
    EXPECT_EQ(write_u32(od, 0x1011, 2, canopen::kEraseSignature), AbortCode::None);
    EXPECT_EQ(erased, 1);
}

TEST_F(EposPDictionaryTest, SaveKeepsTheConfigurationButNotTheProcessData) {
    {
        EposPDictionary dictionary(config());
        canopen::ObjectDictionary& od = dictionary.objects();
        ASSERT_EQ(write_u32(od, 0x1F81, 2, 0x0000'000D), AbortCode::None);
        ASSERT_EQ(write_u32(od, 0x1F89, 0, 1200), AbortCode::None);
        ASSERT_EQ(od.write(0x5281, 1, canopen::encode(std::uint8_t{2})), AbortCode::None);
        ASSERT_EQ(od.write(0xA1C0, 1, canopen::encode(std::int32_t{-7})), AbortCode::None);
        ASSERT_EQ(write_u32(od, 0x1010, 1, canopen::kSaveSignature), AbortCode::None);
    }
    EposPDictionary dictionary(config());
    dictionary.store().load_stored_values();
    const canopen::ObjectDictionary& od = dictionary.objects();
    EXPECT_EQ(u32(od, 0x1F81, 2), 0x0000'000Du);
    EXPECT_EQ(u32(od, 0x1F89, 0), 1200u);
    EXPECT_EQ(od.get_as<std::uint8_t>(0x5281, 1), 2u);
    EXPECT_EQ(od.get_as<std::int32_t>(0xA1C0, 1), 0);
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

const std::filesystem::path kShippedEds = EPOSP_SOURCE_DIR "/device/epos-p.eds";

TEST(EposPEds, ShippedFileIsAFreshExport) {
    EXPECT_EQ(read_file(kShippedEds), epos_p_eds())
        << "regenerate it: cmake --build build --target eds";
}

TEST_F(EposPDictionaryTest, ImportOfTheExportGivesTheDictionaryBack) {
    auto imported = canopen::import_eds(epos_p_eds(), "epos-p.eds");
    ASSERT_TRUE(imported.ok()) << imported.error();
    EXPECT_EQ(imported->device, epos_p_device_info());
    EposPDictionaryConfig defaults = config();
    defaults.node_id = 1;
    defaults.serial_number = 0;
    const EposPDictionary built(std::move(defaults));
    test::expect_same_objects(imported->dictionary, built.objects());
}

} // namespace
} // namespace eposp::device
