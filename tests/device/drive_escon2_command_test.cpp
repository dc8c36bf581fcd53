// `eposp drive escon2` run as a user runs it, and `eposp od` configuring it over its USB port.
#include "eposp_command.hpp"

#include <filesystem>
#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace eposp::device {
namespace {

using testing::HasSubstr;
using testing::Not;

// `drive escon2 ARGUMENTS` with its memory (0x1010) in the test's own directory.
std::string drive_escon2(const std::string& arguments) {
    return "drive escon2 --state-dir " + scratch("state").string() + " " + arguments;
}

TEST(DriveEscon2Command, RunsForItsDurationInVirtualTime) {
    const auto result = eposp(drive_escon2("--for 200ms"));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("escon2: ESCON2 Module 60/30 in virtual time"));
    EXPECT_THAT(result.output, HasSubstr("escon2: stopped in Switch On Disabled after 200ms"));
}

// The machine file: a network file's escon2 entry without its name (docs/escon2.md).
TEST(DriveEscon2Command, TheMachineFileChoosesTheHardware) {
    const auto file = scratch("nano.yaml");
    std::ofstream(file) << "hardware: Nano 24/2\n";
    const auto result = eposp(drive_escon2("--config " + file.string() + " --for 10ms"));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("escon2: ESCON2 Nano 24/2 in virtual time"));
}

TEST(DriveEscon2Command, BadInputIsAUserErrorThatSaysWhy) {
    const auto typo = scratch("typo.yaml");
    std::ofstream(typo) << "hardware: Module 60/30\nparamaters: []\n";
    const auto broken = scratch("broken.yaml");
    std::ofstream(broken) << "hardware: [Nano\n";
    const auto refused = scratch("refused.yaml");
    std::ofstream(refused) << "parameters:\n  - {index: 0x1000, value: 1}\n";
    const auto directory = scratch("machines");
    std::filesystem::create_directory(directory);
    for (const auto& [arguments, message] : {
             std::pair{"--config " + typo.string(),
                       "typo.yaml:2:1: error: unknown key 'paramaters' in 'escon2'"},
             std::pair{"--config " + broken.string(), "broken.yaml:"},
             std::pair{"--config " + refused.string(),
                       "refused.yaml:2:5: error: 0x1000 sub 0: the ESCON2 refuses 1"},
             std::pair{"--config " + directory.string(), "is a directory"},
             std::pair{std::string("--config /nonexistent/escon2.yaml"),
                       "/nonexistent/escon2.yaml"},
             std::pair{std::string("--usb /nonexistent/tty"), "--usb: "},
         }) {
        const auto result = eposp(drive_escon2(arguments + " --for 1ms"));
        EXPECT_EQ(result.exit_code, 1) << arguments << "\n" << result.output;
        EXPECT_THAT(result.output, HasSubstr("eposp drive escon2: ")) << arguments;
        // One "error:" only, also where the message names the file and line itself.
        const auto first = result.output.find("error: ");
        ASSERT_NE(first, std::string::npos) << arguments;
        EXPECT_EQ(result.output.find("error: ", first + 1), std::string::npos) << result.output;
        EXPECT_THAT(result.output, HasSubstr(message)) << arguments << "\n" << result.output;
    }
}

// ESCON2 FW spec 5.1: the same `eposp od` that configures the EPOS P configures the ESCON2 over
// its USB port (maxon serial v2 on a pseudo-terminal); it tells the device by its type 0x1000
// and uses the ESCON2's object types (0x6060 is an INTEGER8, 0x2100 sub 1 an UNSIGNED64). The
// machine file's parameters were written at power-up.
TEST(DriveEscon2Command, OdConfiguresTheEscon2OverItsUsbPort) {
    const auto machine = scratch("machine.yaml");
    std::ofstream(machine) << "hardware: Micro 60/5\n"
                              "parameters:\n"
                              "  - {index: 0x210C, sub: 1, value: 77}\n";
    const std::string od = kEposp + " od --port $port --protocol v2 ";
    const auto result = with_served_port(
        drive_escon2("--config " + machine.string() + " --usb pty"), "USB service port",
        od + "read 0x1000 0 && " + od + "read 0x210C 1 && " + od + "write 0x3142 3 27 && " + od +
            "read 0x3142 3 && " + od + "write 0x6060 0 -120 && " + od + "read 0x6060 0 && " + od +
            "read 0x2100 1 && " + od + "read 0x1008 0 && " + od +
            "write 0x1010 1 save; echo save: $?; " + od + "read 0x1F51 1; echo program: $?; " + od +
            "write 0x1000 0 1; echo read-only: $?",
        scratch("escon2.out"));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("0x1000 sub 0: 131474 (0x00020192)"));
    EXPECT_THAT(result.output, HasSubstr("0x210C sub 1: 77 (0x0000004D)"));
    EXPECT_THAT(result.output, HasSubstr("0x3142 sub 3 := 27 (0x1B)"));
    EXPECT_THAT(result.output, HasSubstr("0x3142 sub 3: 27 (0x1B)"));
    EXPECT_THAT(result.output, HasSubstr("0x6060 sub 0: -120"));
    EXPECT_THAT(result.output, HasSubstr("0x2100 sub 1: 00 00 00 00 00 00 00 00"));
    EXPECT_THAT(result.output, HasSubstr("0x1008 sub 0: ESCON2"));
    EXPECT_THAT(result.output, HasSubstr("save: 0"));
    EXPECT_THAT(result.output, HasSubstr("0x06020000"));
    EXPECT_THAT(result.output, HasSubstr("program: 1"));
    EXPECT_THAT(result.output, HasSubstr("0x06010002"));
    EXPECT_THAT(result.output, HasSubstr("read-only: 1"));
    EXPECT_THAT(result.output, HasSubstr("USB service port: /dev/pts/"));
    EXPECT_THAT(result.output, HasSubstr("escon2: ESCON2 Micro 60/5 in real time"));
    EXPECT_THAT(result.output, HasSubstr("interrupted"));
    EXPECT_THAT(result.output, HasSubstr("0 frame errors"));
}

// 6.2.5: what a host saves over USB is in the device's memory (--state-dir) at the next run.
TEST(DriveEscon2Command, ParametersSavedOverUsbAreThereAtTheNextRun) {
    const std::string od = kEposp + " od --port $port --protocol v2 ";
    const auto saved = with_served_port(drive_escon2("--usb pty"), "USB service port",
                                        od + "write 0x210C 2 99 && " + od + "write 0x1010 1 save",
                                        scratch("first.out"));
    ASSERT_EQ(saved.exit_code, 0) << saved.output;
    const auto next = with_served_port(drive_escon2("--usb pty"), "USB service port",
                                       od + "read 0x210C 2", scratch("second.out"));
    EXPECT_EQ(next.exit_code, 0) << next.output;
    EXPECT_THAT(next.output, HasSubstr("0x210C sub 2: 99 (0x00000063)"));
}

TEST(DriveEscon2Command, OdDumpShowsTheObjectsOfTheEscon2) {
    const auto result =
        with_served_port(drive_escon2("--usb pty"), "USB service port",
                         kEposp + " od --port $port --protocol v2 dump", scratch("dump.out"));
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, HasSubstr("Custom persistent memory"));
    EXPECT_THAT(result.output, HasSubstr("0x6060"));
    EXPECT_THAT(result.output, Not(HasSubstr("0x5F51"))) << "an EPOS P object";
}

TEST(DriveEscon2Command, ExplainsItselfWithHelp) {
    const auto result = eposp("drive escon2 --help");
    EXPECT_EQ(result.exit_code, 0);
    for (const char* option : {"--config", "--usb", "--for"}) {
        EXPECT_THAT(result.output, HasSubstr(option));
    }
    EXPECT_THAT(eposp("drive --help").output, HasSubstr("escon2"));
}

} // namespace
} // namespace eposp::device
