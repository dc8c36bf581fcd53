// `eposp download`, `eposp od` and `eposp watch` as a user runs them: against `eposp serve` on
// its RS-232 pseudo-terminal (maxon serial v1) and on its USB one (v2), in another process.
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/test/test_directory.hpp"
#include "eposp_command.hpp"

#include <algorithm>
#include <cctype>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sstream>

namespace eposp::device {
namespace {

using test::run_command;
using ::testing::HasSubstr;
using ::testing::Not;

constexpr const char* kCounter = R"(PROGRAM Main
VAR counter : DINT; END_VAR
counter := counter + 1;
END_PROGRAM
)";

// No std::regex in this file: g++ 12 warns falsely inside it under -O1 with the sanitizers.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

struct ServedPort {
    const char* serve_option; ///< the link `eposp serve` opens
    const char* printed;      ///< how it prints the port's path
    const char* protocol;     ///< what the clients speak
};
void PrintTo(const ServedPort& port, std::ostream* os) {
    *os << port.serve_option;
}
constexpr ServedPort kRs232{"--serial pty", "RS-232 service port", "v1"};
constexpr ServedPort kUsb{"--usb pty", "USB service port", "v2"};

// Runs `clients` (shell commands using $port) against a port `eposp serve` serves, then ends it.
test::CommandResult with_served_port(const ServedPort& port, const std::string& clients,
                                     const std::string& name) {
    return device::with_served_port(std::string("serve ") + port.serve_option + " --for 20s",
                                    port.printed, clients, scratch(name + ".serve"));
}

class ServiceClients : public ::testing::TestWithParam<ServedPort> {
protected:
    std::string client(const std::string& command) const {
        return kEposp + " " + command + " --port $port --protocol " + GetParam().protocol;
    }
};

TEST_P(ServiceClients, OdReadsAndWritesObjectsAndSaysWhyAnAccessIsRefused) {
    const auto result = with_served_port(
        GetParam(),
        client("od") + " read 0x1000 0 && " + client("od") + " write 0x5005 0 600 && " +
            client("od") + " read 0x5005 0 && " + client("od") + " read 0x1008 0 && " +
            client("od") + " read 0x1234 0; echo refused: $?",
        "od");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("0x1000 sub 0: 405 (0x00000195)\n"));
    EXPECT_THAT(result.output, HasSubstr("0x5005 sub 0 := 600 (0x0258)\n"));
    EXPECT_THAT(result.output, HasSubstr("0x5005 sub 0: 600 (0x0258)\n"));
    EXPECT_THAT(result.output, HasSubstr("0x1008 sub 0: EPOS P\n"));
    EXPECT_THAT(result.output,
                HasSubstr("eposp od: error: 0x06020000 Object does not exist Error\nrefused: 1"));
}

// The store signature is written as a tool writes it: "save" (CiA 301 0x1010); the served
// EPOS P keeps the parameters in its state directory (the test's $XDG_STATE_HOME).
TEST_P(ServiceClients, OdSavesTheParametersWithTheSignatureAsText) {
    const auto result = with_served_port(GetParam(), client("od") + " write 0x1010 1 save",
                                         std::string("save-") + GetParam().protocol);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("0x1010 sub 1 := 1702257011 (0x65766173)\n"));
    EXPECT_TRUE(std::filesystem::exists(test::test_file("xdg-state") / "eposp" / "epos-p" /
                                        "parameters.bin"));
}

TEST_P(ServiceClients, DownloadStartsTheProgramAndWatchSeesItRun) {
    const auto source = write_source("counter.st", kCounter);
    const auto result = with_served_port(
        GetParam(),
        client("download " + source) + " --start cold && " + client("od") + " read 0x1F51 1 && " +
            client("watch Main.counter") + " --every 50ms --for 200ms",
        "download");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, ::testing::ContainsRegex("downloaded [0-9]+ bytes in [0-9.]+ s "
                                                        "\\([0-9]+ bytes/s\\)\n"));
    EXPECT_THAT(result.output, HasSubstr("started (cold start)\n"));
    EXPECT_THAT(result.output, Not(HasSubstr("\r"))); // no progress bar but on a terminal
    EXPECT_THAT(result.output, HasSubstr("0x1F51 sub 1: 1 (0x01)\n")); // started
    // Five samples, the counter growing.
    std::vector<int> counters;
    for (const std::string& line : lines_of(result.output)) {
        constexpr std::string_view kSample = " s  Main.counter=";
        if (const auto at = line.find(kSample); at != std::string::npos) {
            counters.push_back(std::stoi(line.substr(at + kSample.size())));
        }
    }
    ASSERT_EQ(counters.size(), 5u) << result.output;
    EXPECT_GT(counters.front(), 0);
    EXPECT_GT(counters.back(), counters.front());
}

// 804 bytes of RETAIN data: a sound image, but more than the EPOS P's 512 bytes.
TEST_P(ServiceClients, ARefusedDownloadSaysWhyByTheFlashStatus) {
    const auto source = write_source("big.st", R"(PROGRAM Main
VAR RETAIN big : ARRAY[0..200] OF DINT; END_VAR
big[0] := big[0] + 1;
END_PROGRAM
)");
    const auto result =
        with_served_port(GetParam(), client("download " + source) + "; echo exit: $?", "refused");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output,
                HasSubstr("eposp download: error: the device refused the program: 0x08000020 "
                          "Transfer or store Error (flash status 0x1F57 = 0x80: incompatible: a "
                          "sound image this controller cannot run)\nexit: 1"));
}

TEST_P(ServiceClients, WatchWritesAndForcesAVariable) {
    const auto source = write_source("counter.st", kCounter);
    const auto result =
        with_served_port(GetParam(),
                         client("download " + source) + " --start none && " +
                             client("watch --write Main.counter=41 Main.counter") + " && " +
                             client("watch --force Main.counter=7") + " && " + client("od") +
                             " write 0x5F51 0 1 && " + client("watch Main.counter") + " && " +
                             client("watch --unforce Main.counter") + " && " +
                             client("watch Main.nothing") + "; echo unknown: $?",
                         "watch");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Main.counter := 41\n"));
    EXPECT_THAT(result.output, ::testing::ContainsRegex("s  Main\\.counter=41\n"));
    EXPECT_THAT(result.output, HasSubstr("Main.counter forced to 7\n"));
    EXPECT_THAT(result.output, ::testing::ContainsRegex("s  Main\\.counter=7\n")); // running
    EXPECT_THAT(result.output, HasSubstr("Main.counter released\n"));
    EXPECT_THAT(result.output, HasSubstr("eposp watch: error: Main.nothing: 0x06090030"));
    EXPECT_THAT(result.output, HasSubstr("unknown: 1"));
}

// An independent check: a client written in Python from the issue's protocol description alone
// (pyserial on the pseudo-terminal) reads, writes and downloads by segmented transfer.
TEST_P(ServiceClients, AnIndependentPythonClientAgrees) {
    const std::string script =
        std::string(EPOSP_SOURCE_DIR) + "/tests/device/service/maxon_serial_client.py";
    const auto source = write_source("counter.st", kCounter);
    const auto image = scratch("counter.epx");
    const auto built = eposp("build " + source + " -o " + image.string());
    ASSERT_EQ(built.exit_code, 0) << built.output;
    const auto result = with_served_port(GetParam(),
                                         "/usr/bin/python3 " + script + " $port " +
                                             GetParam().protocol + " " + image.string(),
                                         "python");
    if (result.exit_code == 77) {
        GTEST_SKIP() << "pyserial is not installed (Debian: python3-serial)";
    }
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr(std::string(GetParam().protocol) + ": ok\n"));
}

INSTANTIATE_TEST_SUITE_P(BothLinks, ServiceClients, ::testing::Values(kRs232, kUsb),
                         [](const ::testing::TestParamInfo<ServedPort>& param_info) {
                             return std::string(param_info.param.protocol);
                         });

TEST(ServiceClients, ADeviceThatDoesNotAnswerIsATimeout) {
    // The USB port does not understand v1: it never answers.
    const auto result = with_served_port(
        kUsb, kEposp + " od --port $port --protocol v1 read 0x1000 0; echo exit: $?", "timeout");
    EXPECT_THAT(result.output, HasSubstr("eposp od: error: no answer from "));
    EXPECT_THAT(result.output, HasSubstr("(is a device there, speaking v1 (RS-232)?)\nexit: 1"));
}

// Through the gateway: the internal EPOS2 (node 1 on the internal port, network 1) by the
// network-addressed commands of v2; its device name is longer than ReadObject's 4 bytes.
TEST(ServiceClients, OdReachesTheInternalEpos2ThroughTheGateway) {
    const auto result = with_served_port(
        kUsb,
        kEposp + " od --port $port --protocol v2 read 0x1000 0 --network 1 --node 1 && " + kEposp +
            " od --port $port --protocol v2 read 0x1008 0 --network 1 --node 1",
        "gateway");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("0x1000 sub 0: 131474 (0x00020192)\n"));
    EXPECT_THAT(result.output, HasSubstr("0x1008 sub 0: EPOS2\n"));
}

TEST(ServiceClients, OdReachesAPortServedOverTcp) {
    constexpr ServedPort kRs232OverTcp{"--serial tcp:127.0.0.1:0", "RS-232 service port", "v1"};
    const auto result =
        with_served_port(kRs232OverTcp, kEposp + " od --port tcp:$port read 0x1000 0", "tcp");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("0x1000 sub 0: 405 (0x00000195)\n"));
}

// `watch --every` without --for runs until Ctrl-C, which ends it as a success.
TEST(ServiceClients, CtrlCEndsAnEndlessWatch) {
    const auto source = write_source("counter.st", kCounter);
    const auto watched = scratch("watch.out");
    const auto result = with_served_port(
        kRs232,
        kEposp + " download --port $port " + source + " && { " + kEposp +
            " watch --port $port Main.counter --every 50ms > " + watched.string() +
            " 2>&1 & watcher=$!; for i in $(seq 600); do mask=$(sed -n \"s/^SigCgt:\t*//p\" "
            "/proc/$watcher/status); [ -n \"$mask\" ] && [ $(( 0x$mask & 2 )) -ne 0 ] && "
            "grep -q counter " +
            watched.string() + " && break; sleep 0.05; done; kill -INT $watcher; wait $watcher; }",
        "interrupt");
    const std::string output = read_file(watched);
    EXPECT_EQ(result.exit_code, 0) << result.output << output;
    EXPECT_THAT(output, ::testing::ContainsRegex("s  Main\\.counter=[0-9]+\n"));
}

// Over USB (about 4 s; RS-232 takes 20): one row for each entry of the EPOS P's dictionary.
TEST(ServiceClients, OdDumpShowsEveryObjectOfTheEposP) {
    const auto result =
        with_served_port(kUsb, kEposp + " od --port $port --protocol v2 dump", "dump");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("index   sub  name"));
    EXPECT_THAT(result.output,
                ::testing::ContainsRegex("0x1000 +0  Device Type +405 \\(0x00000195\\)\n"));
    EXPECT_THAT(result.output, ::testing::ContainsRegex("0x1008 +0  Device Name +EPOS P\n"));
    EXPECT_THAT(result.output, ::testing::ContainsRegex(
                                   "0x5F60 +4  PLC Variable Access: Unforce +\\(write only\\)\n"));
    const EposPDictionary dictionary(EposPDictionaryConfig{});
    std::size_t entries = 0;
    for (const auto& [index, object] : dictionary.objects().objects()) {
        entries += object.subs.size();
    }
    // A row: "0xIIII", spaces, the sub-index, two spaces, the name ...
    const auto is_row = [](const std::string& line) {
        if (line.size() < 7 || line.compare(0, 2, "0x") != 0 ||
            !std::all_of(line.begin() + 2, line.begin() + 6,
                         [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); })) {
            return false;
        }
        const auto sub = line.find_first_not_of(' ', 6);
        const auto end = line.find_first_not_of("0123456789", sub);
        return sub > 6 && end != std::string::npos && end > sub && line.compare(end, 2, "  ") == 0;
    };
    const auto rows = lines_of(result.output);
    EXPECT_EQ(static_cast<std::size_t>(std::count_if(rows.begin(), rows.end(), is_row)), entries);
}

TEST(ServiceClients, ThePythonClientEncodesTheIssuesByteVectors) {
    const auto result = run_command("/usr/bin/python3 " + std::string(EPOSP_SOURCE_DIR) +
                                    "/tests/device/service/maxon_serial_client.py selftest 2>&1");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("selftest: ok"));
}

TEST(ServiceClients, BadArgumentsAreUserErrors) {
    for (const auto& [arguments, message] : {
             std::pair{"od --port /nonexistent/tty read 0x1000 0", "--port: "},
             std::pair{"od --port /dev/null read 0x10000 0",
                       "INDEX '0x10000' is not an object index"},
             std::pair{"od --port /dev/null write 0x1000 0 70000 --type u16",
                       "VALUE: '70000' is not a u16 value (0 to 65535)"},
             std::pair{"od --port /dev/null read 0x1000 0 --type f32", "--type"},
             std::pair{"watch --port /dev/null --write Main.x", "'Main.x' is not PATH=VALUE"},
             std::pair{"download --port /dev/null missing.st", "missing.st"},
         }) {
        const auto result = eposp(arguments);
        EXPECT_EQ(result.exit_code, 1) << arguments << "\n" << result.output;
        EXPECT_THAT(result.output, HasSubstr(message)) << arguments;
    }
}

TEST(ServiceClients, EachCommandExplainsItselfWithHelp) {
    for (const char* command : {"download", "od", "watch"}) {
        const auto result = eposp(std::string(command) + " --help");
        EXPECT_EQ(result.exit_code, 0) << command;
        EXPECT_THAT(result.output, HasSubstr("--port")) << command;
        EXPECT_THAT(result.output, HasSubstr("--protocol")) << command;
    }
}

} // namespace
} // namespace eposp::device
