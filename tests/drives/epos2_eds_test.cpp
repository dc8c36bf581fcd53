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
    auto imported = canopen::import_eds(read_file(kShippedEds), "epos2.eds");
    ASSERT_TRUE(imported.ok()) << imported.error();
    EXPECT_EQ(imported->device, epos2_device_info());

    Epos2DictionaryConfig config;
    config.node_id = 1;
    config.parameter_file = "never-written.bin";
    const Epos2Dictionary built(std::move(config));
    eposp::test::expect_same_objects(imported->dictionary, built.objects());
}

} // namespace
} // namespace eposp::drives::epos2
