// What the tests of the running ESCON2 share: the states of its statusword (ESCON2 FW spec
// table 6) and a drive on a virtual-time loop with a parameter file of its own.
#pragma once

#include "eposp/drives/escon2/escon2_drive.hpp"

#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <memory>
#include <unistd.h>

namespace eposp::drives::escon2::test {

constexpr std::uint16_t kStateMask = 0x006F;
constexpr std::uint16_t kSwitchOnDisabled = 0x0040;
constexpr std::uint16_t kOperationEnabled = 0x0027;
constexpr std::uint16_t kFault = 0x0008;
constexpr std::uint16_t kWarning = 1U << 7;

class Escon2DriveFixture : public ::testing::Test {
protected:
    Escon2DriveFixture() { std::filesystem::remove(parameter_file()); }
    ~Escon2DriveFixture() override { std::filesystem::remove(parameter_file()); }

    /// One per test and process, so that the suite runs in parallel and twice at once.
    static std::filesystem::path parameter_file() {
        const ::testing::TestInfo& test = *::testing::UnitTest::GetInstance()->current_test_info();
        return std::filesystem::temp_directory_path() /
               fmt::format("escon2-{}-{}-{}.bin", ::getpid(), test.test_suite_name(),
                           test.name());
    }

    /// Powers up a drive of `config`, which keeps its parameters in parameter_file().
    void start(Escon2DriveConfig config = {}) {
        config.dictionary.parameter_file = parameter_file();
        drive = std::make_unique<Escon2Drive>(loop, std::move(config));
        drive->start();
    }

    template <typename T>
    canopen::AbortCode try_write(std::uint16_t index, std::uint8_t sub, T value) {
        return drive->objects().write(index, sub, canopen::encode(value));
    }
    template <typename T>
    void write(std::uint16_t index, std::uint8_t sub, T value) {
        ASSERT_EQ(try_write(index, sub, value), canopen::AbortCode::None)
            << fmt::format("0x{:04X} sub {}", index, sub);
    }
    template <typename T>
    T read(std::uint16_t index, std::uint8_t sub = 0) const {
        return drive->objects().get_as<T>(index, sub);
    }
    std::uint16_t statusword() const { return read<std::uint16_t>(0x6041); }
    std::uint16_t state() const { return statusword() & kStateMask; }
    void controlword(std::uint16_t value) { write(0x6040, 0, value); }
    /// Shutdown, then Enable operation (table 8).
    void enable() {
        controlword(0x06);
        controlword(0x0F);
    }
    void run(std::chrono::milliseconds duration) { loop.run_for(duration); }

    /// Table 110 "d": the error's code, register bits and history entry (the newest), and the
    /// drive disabled at once: in Fault with the power stage off within two control periods,
    /// without a quick stop ramp.
    void expect_disabled_with(std::uint16_t code, std::uint8_t error_register) {
        run(std::chrono::milliseconds(2));
        EXPECT_EQ(state(), kFault);
        EXPECT_EQ(drive->axis().mode(), plant::ControlMode::PowerOff);
        EXPECT_EQ(read<std::uint16_t>(0x603F), code);
        EXPECT_EQ(read<std::uint8_t>(0x1001), error_register);
        EXPECT_GE(read<std::uint8_t>(0x1003, 0), 1u);
        EXPECT_EQ(read<std::uint32_t>(0x1003, 1), code) << "an error: bit 31 clear";
    }

    core::EventLoop loop;
    std::unique_ptr<Escon2Drive> drive;
};

} // namespace eposp::drives::escon2::test
