// `eposp drive epos2` run as a user runs it.
#include "eposp_command.hpp"

#include <filesystem>
#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using testing::HasSubstr;

TEST(DriveCommand, VirtualRunBootsTheDriveAndEndsAfterItsDuration) {
    const auto result = eposp("drive epos2 --node-id 5 --virtual --for 200ms");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("epos2: node 5 on bus can0"));
    EXPECT_THAT(result.output, HasSubstr("stopped in Switch On Disabled"));
}

TEST(DriveCommand, TraceOfAVirtualRunHoldsTheBootUpOfTheDrive) {
    const auto log = scratch("drive.log");
    const auto result = eposp("drive epos2 --node-id 5 --virtual --for 1s --log " + log.string());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string recorded = read_file(log);
    // CiA 301 7.2.8.3.2.2: the boot-up message is the heartbeat COB-ID with state 0x00.
    EXPECT_THAT(recorded, HasSubstr("can0 705#00"));
}

TEST(DriveCommand, VirtualRunWithoutDurationIsAUserError) {
    const auto result = eposp("drive epos2 --virtual");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("--virtual needs --for"));
}

TEST(DriveCommand, NodeIdOutsideOneTo127IsRefused) {
    EXPECT_EQ(eposp("drive epos2 --node-id 128 --virtual --for 1ms").exit_code, 1);
    EXPECT_EQ(eposp("drive epos2 --node-id 0 --virtual --for 1ms").exit_code, 1);
}

TEST(DriveCommand, RunsAtTheBitRatesOfTable8_81AndRefusesOthers) {
    const auto slow = eposp("drive epos2 --bitrate 250000 --virtual --for 200ms");
    EXPECT_EQ(slow.exit_code, 0) << slow.output;
    const auto refused = eposp("drive epos2 --bitrate 100000 --virtual --for 200ms");
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_THAT(refused.output, HasSubstr("an EPOS2 does not run at 100000 bit/s"));
}

// docs/epos2.md: the machine of examples/epos2-drive, and a file with a typo.
TEST(DriveCommand, ConfigFileDescribesTheMachine) {
    const std::string example =
        std::string(EPOSP_SOURCE_DIR) + "/examples/epos2-drive/linear-axis.yaml";
    const auto result =
        eposp("drive epos2 --node-id 3 --config " + example + " --virtual --for 100ms");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("epos2: node 3 on bus can0"));
}

TEST(DriveCommand, BadConfigFileIsAUserErrorWithItsPlace) {
    const auto file = scratch("motor.yaml");
    std::ofstream(file) << "motor:\n  resistence: 2.18\n";
    const auto result = eposp("drive epos2 --config " + file.string() + " --virtual --for 1ms");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output,
                HasSubstr("eposp drive epos2: " + file.string() +
                          ":2:3: error: unknown key 'resistence'"));
    const auto missing = eposp("drive epos2 --config /nonexistent.yaml --virtual --for 1ms");
    EXPECT_EQ(missing.exit_code, 1);
    // The file names itself and says "error:" once, not "error: /nonexistent.yaml: error:".
    EXPECT_THAT(missing.output,
                HasSubstr("eposp drive epos2: /nonexistent.yaml: error: cannot read the file"));
}

// The drive's non-volatile memory (0x1010 / 0x1011, EPOS2 FW spec 8.2.8 / 8.2.9) lives in its
// state directory: by default $XDG_STATE_HOME/eposp/epos2-<node-ID> (the tests point
// XDG_STATE_HOME at their own directory), else --state-dir.
TEST(DriveCommand, NonVolatileMemoryIsInTheDrivesStateDirectoryByDefault) {
    const auto result = eposp("drive epos2 --node-id 5 --virtual --for 10ms");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(std::filesystem::is_directory(scratch("xdg-state") / "eposp" / "epos2-5"));
}

TEST(DriveCommand, StateDirOptionNamesWhereTheParametersAreKept) {
    const auto state = scratch("state");
    std::filesystem::create_directories(state);
    std::ofstream(state / "parameters.bin") << "not a parameter file\n";
    const auto refused =
        eposp("drive epos2 --state-dir " + state.string() + " --virtual --for 10ms");
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_THAT(refused.output, HasSubstr((state / "parameters.bin").string()));
    std::filesystem::remove(state / "parameters.bin");
    EXPECT_EQ(
        eposp("drive epos2 --state-dir " + state.string() + " --virtual --for 10ms").exit_code, 0);
    EXPECT_EQ(eposp("drive epos2 --state-dir /dev/null --virtual --for 10ms").exit_code, 1);
}

} // namespace
} // namespace eposp::device
