// Program download and program control as CiA 302-3 has them (0x1F50, 0x1F51, 0x1F56, 0x1F57),
// the program store behind them, start at power-up (0x5F51) and the variable access 0x5F60
// (docs/service-interface.md, "Program download and program control").
#include "compile_program.hpp"
#include "eposp/canopen/sdo_client.hpp"
#include "eposp/canopen/store_restore_objects.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p.hpp"
#include "eposp/device/error_entry.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/test/test_directory.hpp"
#include "eposp/vm/image_format.hpp"
#include "eposp_command.hpp"

#include <algorithm>
#include <fstream>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <iterator>
#include <memory>

namespace eposp::device {
namespace {

using namespace std::chrono_literals;
using canopen::AbortCode;

constexpr std::uint16_t kProgramDownloadError = 0x6186;

constexpr const char* kCounter = R"(
    PROGRAM Main
    VAR counter : DINT; limit : INT(0..100); END_VAR
    VAR RETAIN kept : DINT; END_VAR
    counter := counter + 1;
    kept := kept + 1;
    END_PROGRAM)";

constexpr const char* kOther = R"(
    PROGRAM Main
    VAR other : DINT; END_VAR
    other := other + 2;
    END_PROGRAM)";

canopen::Bytes image_of(const char* source) {
    return vm::write_image(compile_program(source));
}

std::uint32_t checksum_of(const canopen::Bytes& image) {
    return canopen::decode<std::uint32_t>(std::span(image).subspan(12, 4));
}

AbortCode control(EposP& device, ProgramControlCommand command) {
    return device.objects().write(kCia302ProgramControlIndex, 1,
                                  canopen::encode(static_cast<std::uint8_t>(command)));
}

std::uint8_t status(EposP& device) {
    return device.objects().get_as<std::uint8_t>(kCia302ProgramControlIndex, 1);
}

std::uint32_t flash_status(EposP& device) {
    return device.objects().get_as<std::uint32_t>(kFlashStatusIndex, 1);
}

std::uint32_t identification(EposP& device) {
    return device.objects().get_as<std::uint32_t>(kProgramIdentificationIndex, 1);
}

std::uint16_t newest_error(EposP& device) {
    return ErrorEntry::decode(device.objects().get_as<std::uint32_t>(0x1003, 1)).code;
}

AbortCode write_u32(EposP& device, std::uint16_t index, std::uint8_t sub, std::uint32_t value) {
    return device.objects().write(index, sub, canopen::encode(value));
}

AbortCode write_text(EposP& device, std::uint8_t sub, std::string_view text) {
    return device.objects().write(kVariableAccessIndex, sub, canopen::encode_string(text));
}

std::string read_text(EposP& device, std::uint8_t sub) {
    canopen::Bytes value;
    EXPECT_EQ(device.objects().read(kVariableAccessIndex, sub, value), AbortCode::None);
    return {value.begin(), value.end()};
}

TEST(ProgramDownload, ADownloadLoadsTheProgramStoppedAndIdentifiesIt) {
    EposP device;
    EXPECT_EQ(status(device), 3u);       // no program
    EXPECT_EQ(flash_status(device), 2u); // bits 1..7 = 1: no valid program
    EXPECT_EQ(identification(device), 0u);

    const canopen::Bytes image = image_of(kCounter);
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image), AbortCode::None);
    EXPECT_EQ(status(device), 0u); // stopped
    EXPECT_EQ(flash_status(device), 0u);
    EXPECT_EQ(identification(device), checksum_of(image));
    canopen::Bytes stored;
    ASSERT_EQ(device.objects().read(kProgramDataIndex, 1, stored), AbortCode::None);
    EXPECT_EQ(stored, image);

    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    EXPECT_EQ(status(device), 1u);
    device.loop().run_for(95ms);
    EXPECT_EQ(*device.plc().value_of("Main.counter"), "10");
}

TEST(ProgramDownload, ProgramControlFollowsTheStateMachineOfCia302Part3) {
    EposP device;
    // Without a program only "clear" is accepted.
    for (const auto command : {ProgramControlCommand::Stop, ProgramControlCommand::Start,
                               ProgramControlCommand::Reset}) {
        EXPECT_EQ(control(device, command), AbortCode::DeviceState);
    }
    EXPECT_EQ(control(device, ProgramControlCommand::Clear), AbortCode::None);
    EXPECT_EQ(
        device.objects().write(kCia302ProgramControlIndex, 1, canopen::encode(std::uint8_t{4})),
        AbortCode::InvalidValue);

    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    EXPECT_EQ(control(device, ProgramControlCommand::Start), AbortCode::DeviceState);
    EXPECT_EQ(control(device, ProgramControlCommand::Clear), AbortCode::DeviceState);
    device.loop().run_for(45ms);
    ASSERT_EQ(control(device, ProgramControlCommand::Stop), AbortCode::None);
    EXPECT_EQ(status(device), 0u);
    EXPECT_EQ(control(device, ProgramControlCommand::Stop), AbortCode::None); // already stopped

    // Reset: stopped, back to the initial values at the next start.
    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    device.loop().run_for(5ms);
    ASSERT_EQ(control(device, ProgramControlCommand::Reset), AbortCode::None);
    EXPECT_EQ(status(device), 0u);
    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    device.loop().run_for(5ms);
    EXPECT_EQ(*device.plc().value_of("Main.kept"), "1");

    ASSERT_EQ(control(device, ProgramControlCommand::Stop), AbortCode::None);
    ASSERT_EQ(control(device, ProgramControlCommand::Clear), AbortCode::None);
    EXPECT_EQ(status(device), 3u);
    EXPECT_EQ(identification(device), 0u);
    EXPECT_EQ(flash_status(device), 2u);
    EXPECT_FALSE(device.plc().value_of("Main.counter"));
}

// Each refused image keeps the old program loaded, identified and stored, and says why.
struct RefusedImage {
    const char* name;
    std::function<canopen::Bytes(canopen::Bytes)> spoil;
    std::uint32_t flash_status; ///< 0x1F57: bits 1..7
};

class RefusedDownload : public ::testing::TestWithParam<RefusedImage> {};

TEST_P(RefusedDownload, KeepsTheOldProgramAndSaysWhy) {
    EposPConfig config;
    config.program_file = test::test_file("program.epx");
    EposP device(config);
    const canopen::Bytes old_image = image_of(kCounter);
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, old_image), AbortCode::None);

    const canopen::Bytes spoiled = GetParam().spoil(image_of(kOther));
    EXPECT_EQ(device.objects().write(kProgramDataIndex, 1, spoiled), AbortCode::TransferOrStore);
    EXPECT_EQ(flash_status(device), GetParam().flash_status << 1);
    EXPECT_EQ(newest_error(device), kProgramDownloadError);
    EXPECT_EQ(identification(device), checksum_of(old_image));
    std::ifstream file(config.program_file, std::ios::binary);
    EXPECT_EQ(canopen::Bytes(std::istreambuf_iterator<char>(file), {}), old_image);
    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    device.loop().run_for(15ms);
    EXPECT_EQ(*device.plc().value_of("Main.counter"), "2");
}

INSTANTIATE_TEST_SUITE_P(
    ProgramDownload, RefusedDownload,
    ::testing::Values(RefusedImage{"FlippedByte",
                                   [](canopen::Bytes image) {
                                       image[image.size() / 2] ^= 0x40;
                                       return image;
                                   },
                                   3},
                      RefusedImage{"Truncated",
                                   [](canopen::Bytes image) {
                                       image.resize(std::max<std::size_t>(image.size(), 7) - 7);
                                       return image;
                                   },
                                   3},
                      RefusedImage{"BadMagic",
                                   [](canopen::Bytes image) {
                                       image[0] = 'X';
                                       return image;
                                   },
                                   2},
                      RefusedImage{"OtherVersion",
                                   [](canopen::Bytes image) {
                                       image[4] = static_cast<std::uint8_t>(vm::kImageVersion + 1);
                                       return image;
                                   },
                                   2},
                      RefusedImage{
                          "TooMuchRetainData", // sound, but more RETAIN data than the 512 bytes
                          [](canopen::Bytes) {
                              return image_of(
                                  "PROGRAM Main VAR RETAIN big : ARRAY[1..200] OF DINT; "
                                  "END_VAR END_PROGRAM");
                          },
                          64}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

// The program memory fails (here: its directory is gone): the program in memory stays too.
TEST(ProgramDownload, AProgramFileThatCannotBeWrittenKeepsTheOldProgram) {
    EposPConfig config;
    config.program_file = test::test_file("gone") / "program.epx";
    EposP device(config);
    EXPECT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kCounter)),
              AbortCode::HardwareError);
    EXPECT_EQ(flash_status(device), 5u << 1); // flash write error
    EXPECT_EQ(newest_error(device), 0x5530u); // EEPROM error
    EXPECT_EQ(status(device), 3u);
    EXPECT_EQ(identification(device), 0u);
}

TEST(ProgramDownload, ARunningProgramIsNotReplaced) {
    EposP device;
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    EXPECT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kOther)),
              AbortCode::DeviceState);
    EXPECT_EQ(flash_status(device), 7u << 1); // flash secured
    EXPECT_EQ(status(device), 1u);
    device.loop().run_for(15ms);
    EXPECT_EQ(*device.plc().value_of("Main.counter"), "2");
}

// A program whose image is several kilobytes: many blocks of 127 segments.
std::string long_program() {
    std::string source = "PROGRAM Main VAR counter : DINT; sum : LREAL; END_VAR\n";
    for (int line = 0; line < 200; ++line) {
        source += "sum := sum + INT_TO_LREAL(" + std::to_string(line) + ") * 0.5;\n";
    }
    return source + "counter := counter + 1;\nEND_PROGRAM\n";
}

// The EPOS P's SDO server on port 2 takes a download as the dictionary does, segmented or by
// block transfer.
TEST(ProgramDownload, WorksThroughAnSdoClientOnTheCanBus) {
    for (const auto protocol : {canopen::SdoProtocol::Segmented, canopen::SdoProtocol::Block}) {
        EposP device;
        auto tool = device.external_bus().connect("tool");
        canopen::SdoClient sdo(device.loop(), *tool);
        tool->on_receive([&](const can::Frame& frame) { sdo.on_frame(frame); });
        const canopen::Bytes image = image_of(long_program().c_str());
        ASSERT_GT(image.size(), 3u * 889u); // more than three blocks of 127 segments

        std::optional<AbortCode> downloaded;
        sdo.download(1, kProgramDataIndex, 1, image, [&](AbortCode code) { downloaded = code; },
                     {.protocol = protocol});
        device.loop().run_for(2s);
        ASSERT_EQ(downloaded, AbortCode::None);
        std::optional<std::uint32_t> identified;
        sdo.upload(1, kProgramIdentificationIndex, 1, [&](AbortCode code, canopen::Bytes value) {
            ASSERT_EQ(code, AbortCode::None);
            identified = canopen::decode<std::uint32_t>(value);
        });
        std::optional<AbortCode> started;
        sdo.download(1, kCia302ProgramControlIndex, 1, canopen::encode(std::uint8_t{1}),
                     [&](AbortCode code) { started = code; });
        device.loop().run_for(100ms);
        EXPECT_EQ(identified, checksum_of(image));
        EXPECT_EQ(started, AbortCode::None);
        EXPECT_EQ(status(device), 1u);
    }
}

struct StoredDevice {
    EposPConfig config;
    StoredDevice() {
        config.program_file = test::test_file("program.epx");
        config.parameter_file = test::test_file("parameters.bin");
        config.runtime.retain_file = test::test_file("retain.bin");
    }
    std::unique_ptr<EposP> power_up() const { return std::make_unique<EposP>(config); }
};

TEST(ProgramDownload, TheStoredProgramStartsWarmAfterAPowerCycleAsTheStored5F51Says) {
    const StoredDevice stored;
    auto device = stored.power_up();
    ASSERT_EQ(device->objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    ASSERT_EQ(device->objects().write(kProgramControlIndex, 0, canopen::encode(std::uint16_t{2})),
              AbortCode::None); // warmstart
    device->loop().run_for(45ms);
    ASSERT_EQ(*device->plc().value_of("Main.kept"), "5");
    ASSERT_EQ(write_u32(*device, 0x1010, 1, canopen::kSaveSignature), AbortCode::None);

    device.reset(); // power down: the RETAIN variables are saved
    device = stored.power_up();
    EXPECT_EQ(status(*device), 0u); // loaded, not yet started
    ASSERT_FALSE(device->start_stored_program());
    EXPECT_EQ(status(*device), 1u);
    EXPECT_EQ(device->objects().get_as<std::uint16_t>(kProgramControlIndex, 0), 2u);
    device->loop().run_for(25ms);
    EXPECT_EQ(*device->plc().value_of("Main.counter"), "3");
    EXPECT_EQ(*device->plc().value_of("Main.kept"), "8");
}

// The value list of table 31 holds on the device as in the bare dictionary: 4 starts nothing.
TEST(ProgramDownload, TheEposPProgramControlRefusesCodesBeyondTable31) {
    EposP device;
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    EXPECT_EQ(device.objects().write(kProgramControlIndex, 0, canopen::encode(std::uint16_t{4})),
              AbortCode::InvalidValue);
    EXPECT_EQ(status(device), 0u);
}

// The network file's events are bound to tasks by name: a downloaded program without the bound
// event task is not disturbed by the event (here each SYNC), whatever its tasks' order.
TEST(ProgramDownload, EventsOfTheNetworkFileFollowTheDownloadedProgram) {
    auto network =
        parse_network_file("sync_period: 1ms\nevents:\n  - {task: OnSync, on: sync}\n", "net.yaml");
    ASSERT_TRUE(network) << network.error();
    EposP device;
    device.add_network(*network);
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(R"(
        VAR_GLOBAL never : BOOL; END_VAR
        PROGRAM Count VAR n : DINT; END_VAR n := n + 1; END_PROGRAM
        CONFIGURATION C RESOURCE R ON EPOS_P
            TASK Cyclic (INTERVAL := T#10ms, PRIORITY := 2);
            TASK OnSync (SINGLE := never, PRIORITY := 1);
            PROGRAM Syncs WITH OnSync : Count;
        END_RESOURCE END_CONFIGURATION)")),
              AbortCode::None);
    ASSERT_FALSE(device.bind_event(network->events.front()));
    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    device.loop().run_for(100ms);
    EXPECT_GT(std::stol(*device.plc().value_of("Syncs.n")), 50);

    ASSERT_EQ(control(device, ProgramControlCommand::Stop), AbortCode::None);
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    device.loop().run_for(100ms);
    EXPECT_LE(std::stol(*device.plc().value_of("Main.counter")), 11); // its 10 ms cycles only
}

// Firmware 0102h: the CAN networks boot at power-up, also when the program starts hot (a hot
// start through 0x5F51 later leaves them alone, 8.1).
TEST(ProgramDownload, AHotStartAtPowerUpBootsTheNetworks) {
    const StoredDevice stored;
    auto device = stored.power_up();
    ASSERT_EQ(device->objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    ASSERT_EQ(device->objects().write(kProgramControlIndex, 0, canopen::encode(std::uint16_t{3})),
              AbortCode::None);
    ASSERT_EQ(write_u32(*device, 0x1010, 1, canopen::kSaveSignature), AbortCode::None);
    device = stored.power_up();
    ASSERT_FALSE(device->start_stored_program());
    EXPECT_EQ(device->objects().get_as<std::uint16_t>(kProgramControlIndex, 0), 3u);
    device->loop().run_for(2s);
    EXPECT_TRUE(device->network(kExternalPort).report().network_started);
}

TEST(ProgramDownload, AStoredProgramWithStoppedBootUpStateStaysStopped) {
    const StoredDevice stored;
    auto device = stored.power_up();
    ASSERT_EQ(device->objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    device = stored.power_up();
    ASSERT_FALSE(device->start_stored_program());
    EXPECT_EQ(status(*device), 0u);
    EXPECT_EQ(flash_status(*device), 0u);
}

TEST(ProgramDownload, ErasingIsRefusedWhileTheProgramRunsAndForgetsItOtherwise) {
    const StoredDevice stored;
    auto device = stored.power_up();
    ASSERT_EQ(device->objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    ASSERT_EQ(control(*device, ProgramControlCommand::Start), AbortCode::None);
    EXPECT_EQ(write_u32(*device, 0x1011, 2, canopen::kEraseSignature), AbortCode::DeviceState);
    ASSERT_EQ(control(*device, ProgramControlCommand::Stop), AbortCode::None);
    ASSERT_EQ(write_u32(*device, 0x1011, 2, canopen::kEraseSignature), AbortCode::None);
    EXPECT_EQ(status(*device), 3u);
    EXPECT_FALSE(std::filesystem::exists(stored.config.program_file));
    device = stored.power_up();
    EXPECT_EQ(status(*device), 3u);
}

TEST(ProgramDownload, ADamagedProgramFileLeavesNoProgramAndIsKept) {
    const StoredDevice stored;
    canopen::Bytes image = image_of(kCounter);
    image[image.size() - 1] ^= 0x01;
    std::ofstream(stored.config.program_file, std::ios::binary)
        .write(reinterpret_cast<const char*>(image.data()),
               static_cast<std::streamsize>(image.size()));
    auto device = stored.power_up();
    EXPECT_EQ(status(*device), 3u);
    EXPECT_EQ(flash_status(*device), 3u << 1);
    EXPECT_EQ(newest_error(*device), kProgramDownloadError);
    EXPECT_EQ(std::filesystem::file_size(stored.config.program_file), image.size());
    EXPECT_THAT(device->program_refusal(), ::testing::HasSubstr("checksum"));
    // `eposp serve` says so.
    const auto result = eposp("serve --state-dir " +
                              stored.config.program_file.parent_path().string() + " --for 1ms");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, ::testing::HasSubstr("no program: stored program "));
}

// `eposp serve --state-dir DIR` powers up with the program and parameters stored there.
TEST(ProgramDownload, ServeStartsTheProgramStoredInItsStateDirectory) {
    const std::filesystem::path directory = test::test_file("state");
    {
        EposPConfig config;
        config.program_file = directory / "program.epx";
        config.parameter_file = directory / "parameters.bin";
        std::filesystem::create_directories(directory);
        EposP device(config);
        ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kCounter)),
                  AbortCode::None);
        ASSERT_EQ(
            device.objects().write(kProgramControlIndex, 0, canopen::encode(std::uint16_t{1})),
            AbortCode::None);
        ASSERT_EQ(write_u32(device, 0x1010, 1, canopen::kSaveSignature), AbortCode::None);
    }
    const auto result =
        eposp("serve --state-dir " + directory.string() + " --for 300ms --watch Main.counter");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_THAT(result.output, ::testing::ContainsRegex("Main.counter = [1-9][0-9]*\n"));
    // The network file's events are checked against the stored program.
    const auto network = write_source("events.yaml", "events:\n  - {task: OnSync, on: sync}\n");
    const auto refused =
        eposp("serve --state-dir " + directory.string() + " --network " + network + " --for 1ms");
    EXPECT_EQ(refused.exit_code, 1) << refused.output;
    EXPECT_THAT(refused.output, ::testing::HasSubstr("event task OnSync: the program has no such"));
}

// `eposp serve` keeps the EPOS P's memory without --state-dir too, as a device does: in
// $XDG_STATE_HOME/eposp/epos-p (run_command points it at the test's directory), with the RETAIN
// variables, so that a warm start after a restart goes on counting.
TEST(ProgramDownload, ServeKeepsProgramAndRetainInTheDefaultStateDirectory) {
    const std::filesystem::path directory = test::test_file("xdg-state") / "eposp" / "epos-p";
    std::filesystem::create_directories(directory);
    {
        EposPConfig config;
        config.program_file = directory / "program.epx";
        config.parameter_file = directory / "parameters.bin";
        EposP device(config);
        ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kCounter)),
                  AbortCode::None);
        ASSERT_EQ(
            device.objects().write(kProgramControlIndex, 0, canopen::encode(std::uint16_t{2})),
            AbortCode::None); // warm
        ASSERT_EQ(write_u32(device, 0x1010, 1, canopen::kSaveSignature), AbortCode::None);
    }
    // No std::regex: g++ 12 warns falsely inside it under -O1 with the sanitizers.
    const auto kept_after = [](const std::string& output) {
        constexpr std::string_view kWatched = "Main.kept = ";
        const auto at = output.find(kWatched);
        EXPECT_NE(at, std::string::npos) << output;
        return at == std::string::npos ? 0L : std::stol(output.substr(at + kWatched.size()));
    };
    const auto first = eposp("serve --for 300ms --watch Main.kept");
    ASSERT_EQ(first.exit_code, 0) << first.output;
    const auto second = eposp("serve --for 300ms --watch Main.kept");
    ASSERT_EQ(second.exit_code, 0) << second.output;
    EXPECT_GT(kept_after(first.output), 0);
    EXPECT_GT(kept_after(second.output), kept_after(first.output));
    EXPECT_TRUE(std::filesystem::exists(directory / "retain.bin"));
}

TEST(VariableAccess, ReadsWritesForcesAndUnforcesByPath) {
    EposP device;
    EXPECT_EQ(write_text(device, 1, "Main.counter"), AbortCode::DeviceState); // no program
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kCounter)), AbortCode::None);
    EXPECT_EQ(write_text(device, 1, "Main.nothing"), AbortCode::InvalidValue);
    ASSERT_EQ(write_text(device, 1, "Main.counter"), AbortCode::None);
    ASSERT_EQ(control(device, ProgramControlCommand::Start), AbortCode::None);
    device.loop().run_for(25ms);
    EXPECT_EQ(read_text(device, 2), "3");

    ASSERT_EQ(write_text(device, 2, "16#64"), AbortCode::None); // 100
    device.loop().run_for(10ms);
    EXPECT_EQ(read_text(device, 2), "101");
    EXPECT_EQ(write_text(device, 2, "TRUE"), AbortCode::InvalidValue);
    EXPECT_EQ(write_text(device, 2, "3000000000"), AbortCode::InvalidValue); // beyond DINT

    EXPECT_EQ(read_text(device, 3), ""); // not forced
    ASSERT_EQ(write_text(device, 3, "-5"), AbortCode::None);
    device.loop().run_for(30ms);
    EXPECT_EQ(read_text(device, 2), "-5");
    EXPECT_EQ(read_text(device, 3), "-5");
    ASSERT_EQ(device.objects().write(kVariableAccessIndex, 4, canopen::encode(std::uint8_t{1})),
              AbortCode::None);
    device.loop().run_for(10ms);
    EXPECT_EQ(read_text(device, 2), "-4");
    EXPECT_EQ(read_text(device, 3), "");

    // A subrange variable takes its range only.
    ASSERT_EQ(write_text(device, 1, "Main.limit"), AbortCode::None);
    EXPECT_EQ(write_text(device, 2, "101"), AbortCode::InvalidValue);
    EXPECT_EQ(write_text(device, 2, "INT#100"), AbortCode::None);

    // A path the new program does not have names nothing.
    ASSERT_EQ(control(device, ProgramControlCommand::Stop), AbortCode::None);
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(kOther)), AbortCode::None);
    EXPECT_EQ(read_text(device, 2), "");
    EXPECT_EQ(write_text(device, 2, "1"), AbortCode::TransferOrStore);
}

// The literals 0x5F60 takes, type by type: what is written, and what is read back.
struct Literal {
    const char* path;
    const char* text;
    AbortCode code;
    const char* read_back; ///< the value after the write
};

void PrintTo(const Literal& literal, std::ostream* out) {
    *out << literal.path << " := " << literal.text;
}

class VariableLiteral : public ::testing::TestWithParam<Literal> {};

TEST_P(VariableLiteral, IsTakenOrRefusedAsItsTypeSays) {
    EposP device;
    ASSERT_EQ(device.objects().write(kProgramDataIndex, 1, image_of(R"(
        TYPE Mode : (Idle, Travel, Halt); END_TYPE
        PROGRAM Main
        VAR b : BOOL; s : SINT; us : USINT; w : WORD; l : LINT; ul : ULINT; r : REAL;
            lr : LREAL; m : Mode; t : TIME; END_VAR
        VAR CONSTANT k : INT := 3; END_VAR
        END_PROGRAM)")),
              AbortCode::None);
    const Literal& literal = GetParam();
    ASSERT_EQ(write_text(device, 1, literal.path), AbortCode::None);
    EXPECT_EQ(write_text(device, 2, literal.text), literal.code);
    EXPECT_EQ(read_text(device, 2), literal.read_back);
}

INSTANTIATE_TEST_SUITE_P(
    VariableAccess, VariableLiteral,
    ::testing::Values(
        Literal{"Main.b", "TRUE", AbortCode::None, "TRUE"},
        Literal{"Main.b", "true", AbortCode::None, "TRUE"},
        Literal{"Main.b", "1", AbortCode::None, "TRUE"},
        Literal{"Main.b", "yes", AbortCode::InvalidValue, "FALSE"},
        Literal{"Main.s", "-128", AbortCode::None, "-128"},
        Literal{"Main.s", "128", AbortCode::InvalidValue, "0"},
        Literal{"Main.s", "SINT#16#7F", AbortCode::None, "127"},
        Literal{"Main.us", "2#1111_0000", AbortCode::None, "240"},
        Literal{"Main.us", "256", AbortCode::InvalidValue, "0"},
        Literal{"Main.us", "-1", AbortCode::InvalidValue, "0"},
        Literal{"Main.w", "16#FFFF", AbortCode::None, "65535"},
        Literal{"Main.l", "-9223372036854775808", AbortCode::None, "-9223372036854775808"},
        Literal{"Main.l", "9223372036854775808", AbortCode::InvalidValue, "0"},
        Literal{"Main.ul", "18446744073709551615", AbortCode::None, "18446744073709551615"},
        Literal{"Main.ul", "18446744073709551616", AbortCode::InvalidValue, "0"},
        Literal{"Main.r", "1.5", AbortCode::None, "1.5"},
        Literal{"Main.r", "1E39", AbortCode::InvalidValue, "0"},
        Literal{"Main.r", "1.5x", AbortCode::InvalidValue, "0"},
        Literal{"Main.lr", "-2.5E3", AbortCode::None, "-2500"},
        Literal{"Main.m", "Travel", AbortCode::None, "Travel"},
        Literal{"Main.m", "Mode#Halt", AbortCode::None, "Halt"},
        Literal{"Main.m", "0", AbortCode::None, "Idle"},
        Literal{"Main.m", "Fly", AbortCode::InvalidValue, "Idle"},
        Literal{"Main.t", "T#1s", AbortCode::InvalidValue, "T#0ms"},
        Literal{"Main.k", "4", AbortCode::ReadOnly, "3"}),
    [](const auto& param_info) { return "Case" + std::to_string(param_info.index); });

} // namespace
} // namespace eposp::device
