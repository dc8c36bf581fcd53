// `eposp eds`: the EDS of a simulated device on stdout or into a file.
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using testing::HasSubstr;

TEST(EdsCommand, WritesTheEposPEdsToTheFileGiven) {
    const auto path = scratch("epos-p.eds");
    const auto result = eposp("eds epos-p -o " + path.string());
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_EQ(read_file(path), epos_p_eds());
}

TEST(EdsCommand, PrintsTheEpos2EdsWithoutAFile) {
    const auto result = eposp("eds epos2");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("ProductName=EPOS2 24/5"));
}

TEST(EdsCommand, ADirectoryAsTheOutputIsAUserError) {
    const auto directory = scratch("a-directory");
    std::filesystem::create_directories(directory);
    const auto result = eposp("eds epos-p -o " + directory.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("eposp eds: error:"));
    EXPECT_TRUE(std::filesystem::is_directory(directory));
}

TEST(EdsCommand, AnUnknownDeviceIsAUsageError) {
    const auto result = eposp("eds escon9");
    EXPECT_EQ(result.exit_code, 1);
}

} // namespace
} // namespace eposp::device
