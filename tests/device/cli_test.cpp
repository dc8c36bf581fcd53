// The `eposp` command as a user meets it: exit codes and messages.
#include "eposp_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <ostream>

namespace eposp::device {
namespace {

using testing::HasSubstr;

TEST(Cli, VersionPrintsTheVersion) {
    const auto result = eposp("--version");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("eposp 0."));
}

TEST(Cli, HelpListsTheSubcommands) {
    const auto result = eposp("--help");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_THAT(result.output, HasSubstr("bus"));
}

struct UserErrorCase {
    const char* name;
    const char* arguments;
    const char* message; ///< what the message must mention

    friend void PrintTo(const UserErrorCase& row, std::ostream* out) {
        *out << "eposp " << row.arguments;
    }
};

class UserError : public testing::TestWithParam<UserErrorCase> {};

// Every user error exits with 1 and a message that names what was wrong.
TEST_P(UserError, ExitsWithOneAndSaysWhy) {
    const auto result = eposp(GetParam().arguments);
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_THAT(result.output, HasSubstr(GetParam().message));
    EXPECT_THAT(result.output, testing::Not(HasSubstr("0000000000000000000000")));
}

INSTANTIATE_TEST_SUITE_P(
    Cli, UserError,
    testing::Values(
        UserErrorCase{"MissingSubcommand", "", "subcommand"},
        UserErrorCase{"UnknownOption", "bus --no-such-option", "--no-such-option"},
        UserErrorCase{"MalformedDuration", "bus --virtual --for tomorrow", "not a duration"},
        UserErrorCase{"NonCanopenBitrate", "bus --virtual --bitrate 123456",
                      "not a CANopen bit rate"},
        UserErrorCase{"VirtualTimeWithOutsideClients", "bus --virtual --socketcand 127.0.0.1:0",
                      "--virtual"},
        UserErrorCase{"MalformedListenAddress", "bus --socketcand nowhere:port",
                      "not an address to listen on"},
        UserErrorCase{"MissingReplayFile", "bus --virtual --replay /no/such/file.log",
                      "/no/such/file.log"},
        UserErrorCase{"UnwritableTrace", "bus --virtual --log /no/such/dir/bus.log",
                      "/no/such/dir/bus.log"},
        UserErrorCase{"MissingCanInterface", "bus --socketcan nosuchcan7 --for 1s", "nosuchcan7"},
        UserErrorCase{"UnknownSubcommand", "bogus", "'bogus' is not an eposp command"},
        UserErrorCase{"ReplayOfAFileThatIsNoCandumpLog",
                      "bus --virtual --for 1s --replay " EPOSP_SOURCE_DIR
                      "/examples/two-axis/network.yaml",
                      "network.yaml: not a candump -L log"},
        // Ranges in digits: CLI11's own range of doubles printed 309 of them.
        UserErrorCase{"WatchdogOutOfRange", "run main.st --watchdog 0",
                      "'0' is not a whole number in 1..1000000000000"},
        UserErrorCase{"NsPerInstructionThatOverflows",
                      "run main.st --ns-per-instruction 18446744073709551615",
                      "'18446744073709551615' is not a whole number in 0..1000000000"},
        UserErrorCase{"CycleCostThatOverflowsTheClock",
                      "run main.st --ns-per-instruction 1000000000 --watchdog 1000000000000",
                      "a cycle could last longer than the virtual clock counts"}),
    [](const testing::TestParamInfo<UserErrorCase>& row) { return row.param.name; });

} // namespace
} // namespace eposp::device
