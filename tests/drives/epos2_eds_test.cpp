// The EDS that ships in drives/epos2/ is a fresh export of the dictionary, and reads back to it.
#include "eposp/canopen/eds_import.hpp"
#include "eposp/drives/epos2/epos2_dictionary.hpp"
#include "eposp/drives/epos2/epos2_eds.hpp"

#include <fmt/format.h>
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
        << "regenerate it: cmake --build build --target epos2_eds";
}

// What an EDS carries of a sub-object; persistence and hooks are not part of it (CiA 306).
void expect_same_entry(const canopen::SubObject& imported, const canopen::SubObject& built) {
    EXPECT_EQ(imported.name, built.name);
    EXPECT_EQ(imported.type, built.type);
    EXPECT_EQ(imported.access, built.access);
    EXPECT_EQ(imported.pdo_mappable, built.pdo_mappable);
    EXPECT_EQ(imported.default_value, built.default_value);
    EXPECT_EQ(imported.low_limit, built.low_limit);
    EXPECT_EQ(imported.high_limit, built.high_limit);
}

TEST(Epos2Eds, ImportOfTheShippedFileGivesTheDictionaryBack) {
    auto imported = canopen::import_eds(read_file(kShippedEds), "epos2.eds");
    ASSERT_TRUE(imported.ok()) << imported.error();
    EXPECT_EQ(imported->device, epos2_device_info());

    Epos2DictionaryConfig config;
    config.node_id = 1;
    config.parameter_file = "never-written.bin";
    const Epos2Dictionary built(std::move(config));
    const auto& objects = imported->dictionary.objects();
    ASSERT_EQ(objects.size(), built.objects().objects().size());
    for (const auto& [index, object] : built.objects().objects()) {
        const auto found = objects.find(index);
        ASSERT_NE(found, objects.end()) << fmt::format("0x{:04X}", index);
        EXPECT_EQ(found->second.name, object.name);
        EXPECT_EQ(found->second.code, object.code);
        ASSERT_EQ(found->second.subs.size(), object.subs.size()) << fmt::format("0x{:04X}", index);
        for (const auto& [sub_index, sub] : object.subs) {
            SCOPED_TRACE(fmt::format("0x{:04X} sub {}", index, sub_index));
            expect_same_entry(found->second.subs.at(sub_index), sub);
        }
    }
}

} // namespace
} // namespace eposp::drives::epos2
