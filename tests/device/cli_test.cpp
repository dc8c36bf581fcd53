// The `eposp` command as a user meets it: exit codes and messages.
#include "eposp/test/run_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using test::run_command;
using testing::HasSubstr;

const std::string kEposp = EPOSP_EXECUTABLE;

TEST(Cli, VersionPrintsTheVersion) {
    const auto result = run_command(kEposp + " --version");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("eposp 0."));
}

TEST(Cli, HelpListsTheSubcommands) {
    const auto result = run_command(kEposp + " --help");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("bus"));
}

TEST(Cli, MissingSubcommandIsAUserError) {
    const auto result = run_command(kEposp);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("subcommand"));
}

TEST(Cli, UnknownOptionIsAUserError) {
    const auto result = run_command(kEposp + " bus --no-such-option");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("--no-such-option"));
}

TEST(Cli, MalformedDurationIsAUserError) {
    const auto result = run_command(kEposp + " bus --virtual --for tomorrow");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_THAT(result.output, HasSubstr("not a duration"));
}

} // namespace
} // namespace eposp::device
