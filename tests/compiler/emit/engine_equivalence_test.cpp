// Compiled code against the interpreter, the reference: both run the same program in lock step,
// in slices of varying length, so that runs stop at many different safe points. After every
// run they must agree on the state, the saved activation, the call depth, the instruction count
// and the fault; after every program run, on every byte of memory.

#include "eposp/compiler/compiler.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/native.hpp"
#include "eposp/vm/program.hpp"
#include "eposp/vm/stdlib/clock.hpp"
#include "eposp/vm/stdlib/standard_library.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <optional>
#include <sstream>
#include <string>

namespace eposp::compiler::test {
namespace {

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class Lockstep {
public:
    explicit Lockstep(const std::string& source) {
        vm::stdlib::register_standard_library(natives_);
        vm::stdlib::register_clock(natives_, [this] { return now_ns_; });
        SourceManager sources;
        const std::vector<FileId> files{sources.add("test.st", source)};
        Diagnostics diagnostics;
        auto image = compile(sources, files, diagnostics);
        if (!image) {
            errors_ = render(diagnostics, sources);
            return;
        }
        auto interpreted = vm::link(*image, natives_, vm::Engine::Interpreter);
        auto compiled = vm::link(std::move(*image), natives_, vm::Engine::Compiled);
        if (!interpreted || !compiled) {
            errors_ = "link failed";
            return;
        }
        interpreted_.emplace(std::move(*interpreted));
        compiled_.emplace(std::move(*compiled));
        reference_.emplace(*interpreted_);
        machine_.emplace(*compiled_);
    }

    const std::string& errors() const { return errors_; }
    bool translated() const { return compiled_->engine() == vm::Engine::Compiled; }

    void set_budget(std::uint64_t instructions) {
        for (std::size_t t = 0; t < interpreted_->image().tasks.size(); ++t) {
            reference_->set_budget(t, instructions);
            machine_->set_budget(t, instructions);
        }
    }

    /// Runs `cycles` cycles of every task; stops at the first disagreement or fault.
    void run(int cycles) {
        const auto& tasks = interpreted_->image().tasks;
        for (int cycle = 0; cycle < cycles; ++cycle) {
            for (std::size_t t = 0; t < tasks.size(); ++t) {
                for (std::size_t e = 0; e < tasks[t].entries.size(); ++e) {
                    if (!run_entry(t, e)) {
                        return;
                    }
                }
            }
            now_ns_ += 1'000'000;
        }
    }

    const vm::TaskState& task(std::size_t t) const { return machine_->task(t); }
    std::string fault(std::size_t t) const { return machine_->describe_fault(t); }

private:
    // Slices from 1 to 200 instructions, in an order that does not repeat quickly.
    std::uint64_t next_slice() {
        seed_ = seed_ * 1103515245U + 12345U;
        return 1 + (seed_ >> 16) % 200;
    }

    bool run_entry(std::size_t t, std::size_t e) {
        reference_->start(t, e);
        machine_->start(t, e);
        for (;;) {
            const auto slice = next_slice();
            const auto expected = reference_->run(t, slice);
            const auto state = machine_->run(t, slice);
            const vm::TaskState& a = reference_->task(t);
            const vm::TaskState& b = machine_->task(t);
            EXPECT_EQ(state, expected);
            EXPECT_EQ(b.executed, a.executed);
            EXPECT_EQ(b.depth, a.depth);
            if (state == vm::RunState::Suspended) {
                EXPECT_EQ(b.current.pc, a.current.pc);
                EXPECT_EQ(b.current.pou, a.current.pou);
                EXPECT_EQ(b.current.frame, a.current.frame);
                EXPECT_EQ(b.current.self, a.current.self);
            }
            if (testing::Test::HasFailure()) {
                return false;
            }
            if (state != vm::RunState::Suspended) {
                break;
            }
        }
        EXPECT_TRUE(std::equal(reference_->memory().begin(), reference_->memory().end(),
                               machine_->memory().begin()))
            << "memory differs after task " << t << ", entry " << e;
        if (reference_->task(t).state == vm::RunState::Faulted) {
            const auto& a = reference_->task(t).fault;
            const auto& b = machine_->task(t).fault;
            EXPECT_EQ(b.trap, a.trap);
            EXPECT_EQ(b.pou, a.pou);
            EXPECT_EQ(b.instruction, a.instruction);
            EXPECT_EQ(b.line, a.line);
            EXPECT_EQ(b.native_reason, a.native_reason);
            return false;
        }
        return !testing::Test::HasFailure();
    }

    std::int64_t now_ns_ = 0;
    std::uint32_t seed_ = 1;
    vm::NativeRegistry natives_;
    std::optional<vm::Program> interpreted_;
    std::optional<vm::Program> compiled_;
    std::optional<vm::Machine> reference_;
    std::optional<vm::Machine> machine_;
    std::string errors_;
};

class EngineEquivalence : public testing::TestWithParam<const char*> {};

TEST_P(EngineEquivalence, CompiledCodeRunsAsTheInterpreter) {
    Lockstep lockstep(read_file(std::string(EPOSP_SOURCE_DIR) + "/" + GetParam()));
    ASSERT_EQ(lockstep.errors(), "");
    if (!lockstep.translated()) {
        GTEST_SKIP() << "this build or machine has no translator to machine code";
    }
    lockstep.run(12);
    EXPECT_EQ(lockstep.task(0).state, vm::RunState::Finished);
}

INSTANTIATE_TEST_SUITE_P(
    Programs, EngineEquivalence,
    testing::Values("tests/compiler/inputs/bubble_sort.st", "tests/compiler/inputs/sieve.st",
                    "tests/compiler/inputs/crc32.st", "tests/compiler/inputs/pid_plant.st",
                    "tests/compiler/inputs/conveyor_fsm.st", "tests/compiler/inputs/fb_channels.st",
                    "tests/compiler/inputs/strings.st", "tests/compiler/inputs/program_calls.st",
                    "tests/fuzz/corpus/st_compiler/codesys_style.st",
                    "tests/fuzz/corpus/st_compiler/types_and_calls.st",
                    "tests/fuzz/corpus/st_compiler/type_defaults.st",
                    "examples/plc-basics/blinker.st"),
    [](const testing::TestParamInfo<const char*>& program) {
        std::string name = program.param;
        name = name.substr(name.rfind('/') + 1);
        name = name.substr(0, name.find('.'));
        return name;
    });

// Each program stops with a run-time error; both engines must stop at the same instruction,
// with the same count, fault and memory.
struct Faulting {
    const char* name;
    const char* source;
};

class EngineFaults : public testing::TestWithParam<Faulting> {};

TEST_P(EngineFaults, StopWhereTheInterpreterStops) {
    Lockstep lockstep(GetParam().source);
    ASSERT_EQ(lockstep.errors(), "");
    lockstep.run(3);
    EXPECT_EQ(lockstep.task(0).state, vm::RunState::Faulted);
}

constexpr const char* kConfiguration = R"(
CONFIGURATION Config0
  RESOURCE Res0 ON PLC
    TASK T(INTERVAL := T#1ms, PRIORITY := 1);
    PROGRAM Inst0 WITH T : Main;
  END_RESOURCE
END_CONFIGURATION
)";

std::string with_configuration(const std::string& program) {
    return program + kConfiguration;
}

const std::string kDivisionInInlinedCallee = with_configuration(R"(
FUNCTION Ratio : DINT
  VAR_INPUT a, b : DINT; END_VAR
  Ratio := a / b;
END_FUNCTION
PROGRAM Main
  VAR i : DINT; s : DINT; END_VAR
  FOR i := 3 TO -3 BY -1 DO s := s + Ratio(100, i); END_FOR;
END_PROGRAM
)");

const std::string kIndexOutOfRange = with_configuration(R"(
PROGRAM Main
  VAR a : ARRAY[1..10] OF INT; i : INT; n : INT; END_VAR
  n := n + 4;
  FOR i := 1 TO n DO a[i] := a[i] + i; END_FOR;
END_PROGRAM
)");

const std::string kNullInstance = with_configuration(R"(
FUNCTION_BLOCK Counter
  VAR_OUTPUT n : DINT; END_VAR
  n := n + 1;
END_FUNCTION_BLOCK
PROGRAM Main
  VAR c : Counter; p : POINTER TO Counter; k : DINT; END_VAR
  k := k + 1;
  IF k < 3 THEN p := ADR(c); ELSE p := NULL; END_IF;
  p^();
END_PROGRAM
)");

const std::string kSubrange = with_configuration(R"(
PROGRAM Main
  VAR s : INT(0..20); k : INT; END_VAR
  k := k + 9;
  s := k;
END_PROGRAM
)");

const std::string kBudget = with_configuration(R"(
PROGRAM Main
  VAR i : DINT; END_VAR
  WHILE TRUE DO i := i + 1; END_WHILE;
END_PROGRAM
)");

INSTANTIATE_TEST_SUITE_P(Traps, EngineFaults,
                         testing::Values(Faulting{"DivisionInInlinedCallee",
                                                  kDivisionInInlinedCallee.c_str()},
                                         Faulting{"IndexOutOfRange", kIndexOutOfRange.c_str()},
                                         Faulting{"NullInstance", kNullInstance.c_str()},
                                         Faulting{"Subrange", kSubrange.c_str()}),
                         [](const testing::TestParamInfo<Faulting>& program) {
                             return std::string(program.param.name);
                         });

TEST(EngineBudget, AnEndlessLoopExceedsTheBudgetAtTheSameInstruction) {
    Lockstep lockstep(kBudget);
    ASSERT_EQ(lockstep.errors(), "");
    lockstep.set_budget(10'007);
    lockstep.run(1);
    EXPECT_EQ(lockstep.task(0).state, vm::RunState::Faulted);
    EXPECT_EQ(lockstep.task(0).fault.trap, vm::Trap::BudgetExceeded);
}

} // namespace
} // namespace eposp::compiler::test
