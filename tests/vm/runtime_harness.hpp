#pragma once

// Compiles an ST application and loads it into a PlcRuntime on a virtual-time event loop,
// collecting the errors it raises: the shape of the runtime's end-to-end tests.

#include "eposp/compiler/compiler.hpp"
#include "eposp/compiler/diagnostics.hpp"
#include "eposp/compiler/source_manager.hpp"
#include "eposp/vm/plc_runtime.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"
#include "eposp/vm/symbol_lookup.hpp"

#include <chrono>
#include <cstring>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace eposp::vm::test {

struct RaisedError {
    std::uint16_t code = 0;
    std::string text;
};

class RuntimeHarness {
public:
    explicit RuntimeHarness(RuntimeConfig config = {}) {
        stdlib::register_standard_library(natives_);
        stdlib::register_clock(natives_, [this] { return loop.now().time_since_epoch().count(); });
        runtime = std::make_unique<PlcRuntime>(loop, natives_, std::move(config),
                                               [this](std::uint16_t code, std::string text) {
                                                   errors.push_back({code, std::move(text)});
                                               });
    }

    /// The image of `source`, or nullopt with a test failure showing the diagnostics.
    static std::optional<Image> compile_st(const std::string& source) {
        compiler::SourceManager sources;
        const compiler::FileId file = sources.add("test.st", source);
        compiler::Diagnostics diagnostics;
        auto image = compiler::compile(sources, {&file, 1}, diagnostics);
        if (!image) {
            ADD_FAILURE() << compiler::render(diagnostics, sources);
        }
        return image;
    }

    /// Compiles and loads; the load error, empty on success.
    std::string load(const std::string& source) {
        auto image = compile_st(source);
        if (!image) {
            return "does not compile";
        }
        const auto error = runtime->load(std::move(*image));
        return error ? error->message : "";
    }

    void run_until(core::Duration t) { loop.run_until(core::TimePoint{t}); }

    template <typename T>
    T get(std::string_view path) const {
        const auto location = lookup_variable(runtime->image(), path);
        EXPECT_TRUE(location) << location.error();
        T value{};
        if (location) {
            std::memcpy(&value, runtime->memory().data() + location->offset, sizeof(T));
        }
        return value;
    }

    /// The error codes raised so far, in order.
    std::vector<std::uint16_t> error_codes() const {
        std::vector<std::uint16_t> codes;
        for (const RaisedError& error : errors) {
            codes.push_back(error.code);
        }
        return codes;
    }

    core::EventLoop loop;
    std::vector<RaisedError> errors;
    std::unique_ptr<PlcRuntime> runtime;

private:
    NativeRegistry natives_;
};

} // namespace eposp::vm::test
