// The EDS that ships in drives/epos2/ is a fresh export of the dictionary, and reads back to it.
#include "eposp/canopen/eds_import.hpp"
#include "eposp/drives/epos2/epos2_dictionary.hpp"
#include "eposp/drives/epos2/epos2_eds.hpp"
#include "eposp/test/same_dictionary.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace eposp::drives::epos2 {
namespace {

const char* const kShippedEds = EPOSP_SOURCE_DIR "/drives/epos2/epos2.eds";

std::string read_file(const char* path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(Epos2Eds, ShippedFileIsAFreshExport) {
    EXPECT_EQ(read_file(kShippedEds), epos2_eds())
        << "regenerate it: cmake --build build --target eds";
}

TEST(Epos2Eds, ImportOfTheShippedFileGivesTheDictionaryBack) {
    auto imported = canopen::import_eds(read_file(kShippedEds), "epos2.eds", canopen::NodeId{1});
    ASSERT_TRUE(imported.ok()) << imported.error();
    EXPECT_EQ(imported->device, epos2_device_info());

    Epos2DictionaryConfig config;
    config.node_id = 1;
    config.parameter_file = "never-written.bin";
    const Epos2Dictionary built(std::move(config));
    eposp::test::expect_same_objects(imported->dictionary, built.objects());
}

// CiA 306: the COB-IDs chapter 8 gives as "… + Node ID" are $NODEID expressions, so that each
// node read from the file gets its own (8.2.13, 8.2.14, 8.2.18, 8.2.26); the access of the receive
// PDO objects of table 8-77 is rww.
TEST(Epos2Eds, NodeDependentDefaultsFollowTheNodeIdOfTheImport) {
    const std::string eds = read_file(kShippedEds);
    EXPECT_NE(eds.find("[1014]\nParameterName=COB-ID EMCY\nObjectType=0x7\nDataType=0x0007\n"
                       "AccessType=rw\nDefaultValue=$NODEID+0x00000080\n"),
              std::string::npos);
    auto imported = canopen::import_eds(eds, "epos2.eds", canopen::NodeId{5});
    ASSERT_TRUE(imported.ok()) << imported.error();
    const canopen::ObjectDictionary& od = imported->dictionary;
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1014, 0), 0x85U);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1200, 1), 0x605U);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1200, 2), 0x585U);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1400, 1), 0x205U);
    EXPECT_EQ(od.get_as<std::uint32_t>(0x1803, 1), 0xC0000485U);
    EXPECT_EQ(od.find(0x6040, 0)->access, canopen::Access::ReadWriteOutput);
    EXPECT_EQ(od.find(0x6041, 0)->access, canopen::Access::ReadOnly);
}

} // namespace
} // namespace eposp::drives::epos2
