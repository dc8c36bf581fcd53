#pragma once

// An ST program with the motion library on a PLC runtime in virtual time, its axes behind a
// FakeDriveLink: each cycle() is one SYNC followed by one run of the program's 1 ms task.

#include "eposp/compiler/compiler.hpp"
#include "eposp/plcopen/motion_library.hpp"
#include "eposp/vm/plc_runtime.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/symbol_lookup.hpp"
#include "fake_drive_link.hpp"

#include <chrono>
#include <cstring>
#include <gtest/gtest.h>
#include <memory>
#include <string>

namespace eposp::plcopen::test {

/// The name of a test's engine parameter, for INSTANTIATE_TEST_SUITE_P.
inline std::string engine_name(const testing::TestParamInfo<vm::Engine>& param) {
    return param.param == vm::Engine::Interpreter ? "Interpreter" : "Compiled";
}

class MotionHarness {
public:
    explicit MotionHarness(vm::Engine engine = vm::default_engine()) : library(link) {
        vm::RuntimeConfig config;
        config.engine = engine;
        vm::stdlib::register_standard_library(natives_);
        vm::stdlib::register_clock(natives_,
                                   [this] { return loop.now().time_since_epoch().count(); });
        library.register_blocks(natives_);
        runtime = std::make_unique<vm::PlcRuntime>(
            loop, natives_, std::move(config),
            [this](std::uint16_t, std::string text) { errors.push_back(std::move(text)); });
        for (AxisNumber axis = 0; axis < 2; ++axis) {
            link.drives[axis].presence = AxisPresence::Ready;
        }
    }

    /// The image of `source` compiled with the motion library; nullopt (and a test failure
    /// showing the diagnostics) when it does not compile.
    static std::optional<vm::Image> compile(const std::string& source,
                                            std::string* diagnostics_text = nullptr) {
        compiler::SourceManager sources;
        const compiler::FileId file = sources.add("test.st", source);
        const compiler::FileId library_file = sources.add("<plcopen>", MotionLibrary::source());
        compiler::Diagnostics diagnostics;
        auto image = compiler::compile(sources, {&file, 1}, diagnostics, {&library_file, 1});
        if (diagnostics_text != nullptr) {
            *diagnostics_text = compiler::render(diagnostics, sources);
        } else if (!image) {
            ADD_FAILURE() << compiler::render(diagnostics, sources);
        }
        return image;
    }

    /// Compiles, loads and starts `source` (a PROGRAM Main, run every millisecond).
    void start(const std::string& source) {
        const std::string program = source + R"ST(
CONFIGURATION Config
  RESOURCE Cpu ON EPOS_P
    TASK Cyclic (INTERVAL := T#1ms, PRIORITY := 1);
    PROGRAM Main WITH Cyclic : Main;
  END_RESOURCE
END_CONFIGURATION
)ST";
        auto image = compile(program);
        ASSERT_TRUE(image);
        const auto error = runtime->load(std::move(*image));
        ASSERT_FALSE(error) << error->message;
        runtime->start(vm::StartMode::Cold);
    }

    /// One SYNC, then one PLC cycle.
    void cycle(int count = 1) {
        for (int i = 0; i < count; ++i) {
            link.sync();
            loop.run_for(std::chrono::milliseconds(1));
        }
    }

    template <typename T>
    T get(std::string_view path) const {
        const auto location = vm::lookup_variable(runtime->image(), "Main." + std::string(path));
        EXPECT_TRUE(location) << location.error();
        T value{};
        if (location) {
            std::memcpy(&value, runtime->memory().data() + location->offset, sizeof(T));
        }
        return value;
    }
    bool flag(std::string_view path) const { return get<std::uint8_t>(path) != 0; }
    template <typename T>
    void set(std::string_view path, T value) {
        const auto error = runtime->write_value("Main." + std::string(path), value);
        ASSERT_FALSE(error) << error->message;
    }
    void set_flag(std::string_view path, bool value) { set<std::uint8_t>(path, value ? 1 : 0); }

    core::EventLoop loop;
    FakeDriveLink link;
    MotionLibrary library;
    std::unique_ptr<vm::PlcRuntime> runtime;
    std::vector<std::string> errors;

private:
    vm::NativeRegistry natives_;
};

} // namespace eposp::plcopen::test
