// Native function blocks (vm/native.hpp, compile()'s linked libraries): declared in ST, bodies
// in C++, on both engines.

#include "eposp/compiler/compiler.hpp"
#include "eposp/plcopen/block_interface.hpp"
#include "eposp/vm/plc_runtime.hpp"
#include "eposp/vm/symbol_lookup.hpp"
#include "motion_harness.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <gtest/gtest.h>

namespace eposp::plcopen {
namespace {

// A library of one native block: Out := In * 2, counting its calls in a VAR.
const BlockInterface kDoubler{"DOUBLER",
                              {{Section::Input, "In", "DINT", vm::Scalar::I32},
                               {Section::Input, "Fail", "BOOL", vm::Scalar::Bool},
                               {Section::Output, "Out", "DINT", vm::Scalar::I32},
                               {Section::Var, "Calls", "UDINT", vm::Scalar::U32}}};

constexpr std::string_view kLibraryExtra = R"ST(
FUNCTION_BLOCK UNUSED_NATIVE
  VAR_INPUT x : BOOL; END_VAR
END_FUNCTION_BLOCK

FUNCTION_BLOCK ST_HELPER
  VAR_INPUT a : DINT; END_VAR
  VAR_OUTPUT b : DINT; END_VAR
  b := a + 1;
END_FUNCTION_BLOCK
)ST";

constexpr std::string_view kProgram = R"ST(
PROGRAM Main
VAR
  d : DOUBLER;
  h : ST_HELPER;
  x : DINT := 20;
  y, z, times : DINT;
  fail, fail_inside : BOOL;
  w : Wrapper;
END_VAR
d(In := x, Fail := fail, Out => y);
h(a := y, b => z);
x := x + 1;
w(go := fail_inside, times := times);
END_PROGRAM

FUNCTION_BLOCK Wrapper
VAR_INPUT go : BOOL; times : DINT; END_VAR
VAR inner : DOUBLER; i : DINT; END_VAR
IF go THEN
  inner(In := 1, Fail := TRUE);
END_IF;
FOR i := 1 TO times DO
  inner(In := i);
END_FOR;
END_FUNCTION_BLOCK
)ST";

std::optional<vm::Image> compile(std::string_view program, std::string_view library,
                                 std::string& diagnostics_text) {
    compiler::SourceManager sources;
    const compiler::FileId file = sources.add("main.st", std::string(program));
    const compiler::FileId linked = sources.add("<library>", std::string(library));
    compiler::Diagnostics diagnostics;
    auto image = compiler::compile(sources, {&file, 1}, diagnostics, {&linked, 1});
    diagnostics_text = compiler::render(diagnostics, sources);
    return image;
}

void register_doubler(vm::NativeRegistry& registry, std::vector<vm::Scalar> fields) {
    registry.add_block("DOUBLER", std::move(fields), [](vm::NativeBlock& block) {
        if (block.get<std::uint8_t>(1) != 0) {
            block.args().fail("the doubler was told to fail");
            return;
        }
        block.set<std::int32_t>(2, block.get<std::int32_t>(0) * 2);
        block.set<std::uint32_t>(3, block.get<std::uint32_t>(3) + 1);
    });
}

/// The program with DOUBLER's C++ body on a PLC runtime in virtual time.
struct DoublerRuntime {
    void load(vm::Engine engine, std::vector<vm::Scalar> fields = kDoubler.fields()) {
        std::string diagnostics;
        auto image =
            compile(kProgram, kDoubler.declaration() + std::string(kLibraryExtra), diagnostics);
        ASSERT_TRUE(image) << diagnostics;
        register_doubler(natives, std::move(fields));
        vm::RuntimeConfig config;
        config.engine = engine;
        runtime = std::make_unique<vm::PlcRuntime>(
            loop, natives, std::move(config),
            [this](std::uint16_t, std::string text) { errors.push_back(std::move(text)); });
        if (const auto error = runtime->load(std::move(*image))) {
            load_error = error->message;
            return;
        }
        runtime->start(vm::StartMode::Cold);
    }
    std::string value(std::string_view path) const {
        const auto text = runtime->read("Main." + std::string(path));
        return text ? *text : text.error();
    }

    core::EventLoop loop;
    vm::NativeRegistry natives;
    std::unique_ptr<vm::PlcRuntime> runtime;
    std::vector<std::string> errors;
    std::string load_error;
};

class NativeBlocks : public testing::TestWithParam<vm::Engine>, protected DoublerRuntime {
protected:
    void load(std::vector<vm::Scalar> fields = kDoubler.fields()) {
        DoublerRuntime::load(GetParam(), std::move(fields));
    }
};

TEST_P(NativeBlocks, RunItsCppBodyOnItsInstance) {
    load();
    ASSERT_EQ(load_error, "");
    loop.run_for(std::chrono::milliseconds(35)); // a 10 ms task: cycles at 0, 10, 20, 30
    EXPECT_EQ(value("y"), "46");
    EXPECT_EQ(value("z"), "47");
    EXPECT_EQ(value("d.Calls"), "4");
    EXPECT_TRUE(errors.empty());
}

TEST_P(NativeBlocks, AFailureIsARunTimeErrorOfTheCallingPou) {
    load();
    ASSERT_EQ(load_error, "");
    loop.run_for(std::chrono::milliseconds(5));
    ASSERT_FALSE(runtime->write_value<std::uint8_t>("Main.fail", 1));
    loop.run_for(std::chrono::milliseconds(10));
    ASSERT_EQ(errors.size(), 1U);
    EXPECT_NE(errors[0].find("the doubler was told to fail"), std::string::npos) << errors[0];
    // At the call in the program's own source, naming the block: its body has no source.
    EXPECT_NE(errors[0].find("DOUBLER: the doubler was told to fail in Main at line 11"),
              std::string::npos)
        << errors[0];
}

TEST_P(NativeBlocks, AFailureInsideAnotherBlockIsAtThatBlocksCall) {
    load();
    ASSERT_EQ(load_error, "");
    ASSERT_FALSE(runtime->write_value<std::uint8_t>("Main.fail_inside", 1));
    loop.run_for(std::chrono::milliseconds(10));
    ASSERT_EQ(errors.size(), 1U);
    EXPECT_NE(errors[0].find("DOUBLER: the doubler was told to fail in Wrapper at line 21"),
              std::string::npos)
        << errors[0];
}

TEST_P(NativeBlocks, ABodyForAnotherLayoutIsRefusedAtLoad) {
    load({vm::Scalar::I32, vm::Scalar::Bool, vm::Scalar::I16, vm::Scalar::U32});
    EXPECT_NE(load_error.find("DOUBLER has a different signature"), std::string::npos)
        << load_error;
}

// Native calls count as instructions like any other: the watchdog stops a loop of them.
TEST_P(NativeBlocks, TheWatchdogStopsALoopOfCalls) {
    load();
    ASSERT_EQ(load_error, "");
    loop.run_for(std::chrono::milliseconds(5));
    const std::uint64_t per_cycle = runtime->statistics(0).instructions_last;
    runtime->set_watchdog(0, per_cycle + 1000);
    ASSERT_FALSE(runtime->write_value<std::int32_t>("Main.times", 10));
    loop.run_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(errors.empty()) << errors[0];
    ASSERT_FALSE(runtime->write_value<std::int32_t>("Main.times", 1000));
    loop.run_for(std::chrono::milliseconds(10));
    ASSERT_EQ(errors.size(), 1U);
    EXPECT_NE(errors[0].find("in Wrapper"), std::string::npos) << errors[0];
}

TEST(NativeBlockEngines, BothEnginesExecuteTheSameInstructions) {
    DoublerRuntime interpreter;
    DoublerRuntime compiled;
    interpreter.load(vm::Engine::Interpreter);
    compiled.load(vm::Engine::Compiled);
    for (DoublerRuntime* run : {&interpreter, &compiled}) {
        ASSERT_EQ(run->load_error, "");
        ASSERT_FALSE(run->runtime->write_value<std::int32_t>("Main.times", 7));
        run->loop.run_for(std::chrono::milliseconds(35));
    }
    EXPECT_EQ(interpreter.runtime->statistics(0).instructions_last,
              compiled.runtime->statistics(0).instructions_last);
    // 7 calls in each cycle after `times` was set: at 10, 20 and 30 ms.
    EXPECT_EQ(interpreter.value("w.inner.Calls"), "21");
    EXPECT_EQ(compiled.value("w.inner.Calls"), "21");
}

INSTANTIATE_TEST_SUITE_P(Engines, NativeBlocks,
                         testing::Values(vm::Engine::Interpreter, vm::Engine::Compiled),
                         test::engine_name);

TEST(LinkedLibraries, OnlyTheBlocksAProgramCallsAreInItsImage) {
    std::string diagnostics;
    const auto image =
        compile(kProgram, kDoubler.declaration() + std::string(kLibraryExtra), diagnostics);
    ASSERT_TRUE(image) << diagnostics;
    const auto has_pou = [&](std::string_view name) {
        return std::any_of(image->pous.begin(), image->pous.end(),
                           [&](const vm::Pou& pou) { return pou.name == name; });
    };
    EXPECT_TRUE(has_pou("DOUBLER"));
    EXPECT_TRUE(has_pou("ST_HELPER"));
    EXPECT_FALSE(has_pou("UNUSED_NATIVE"));
    ASSERT_EQ(image->imports.size(), 1U);
    EXPECT_EQ(image->imports[0].name, "DOUBLER");
    EXPECT_EQ(image->imports[0].signature.instance, kDoubler.fields());
    // Library warnings (unassigned outputs of a native block) are not the user's business.
    EXPECT_EQ(diagnostics.find("warning"), std::string::npos) << diagnostics;
}

TEST(LinkedLibraries, ANativeBlockHoldsOnlyElementaryVariables) {
    std::string diagnostics;
    const auto image = compile("PROGRAM Main VAR b : BAD; END_VAR b(); END_PROGRAM",
                               R"ST(
FUNCTION_BLOCK BAD
  VAR_INPUT s : STRING; END_VAR
END_FUNCTION_BLOCK
)ST",
                               diagnostics);
    EXPECT_FALSE(image);
    EXPECT_NE(diagnostics.find("a native block's variables are elementary or VAR_IN_OUT"),
              std::string::npos)
        << diagnostics;
}

TEST(LinkedLibraries, TheDeclarationComesFromTheInterface) {
    EXPECT_EQ(kDoubler.declaration(), R"(FUNCTION_BLOCK DOUBLER
  VAR_INPUT
    In : DINT;
    Fail : BOOL;
  END_VAR
  VAR_OUTPUT
    Out : DINT;
  END_VAR
  VAR
    Calls : UDINT;
  END_VAR
END_FUNCTION_BLOCK
)");
}

} // namespace
} // namespace eposp::plcopen
