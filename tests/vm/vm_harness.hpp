#pragma once

// Assembles a one-task application around a PROGRAM Main whose body a test emits, links it
// and runs it: the shape most VM tests need, so each test shows only its instructions.

#include "eposp/vm/builder.hpp"
#include "eposp/vm/machine.hpp"
#include "eposp/vm/program.hpp"

#include <cstring>
#include <gtest/gtest.h>
#include <optional>

namespace eposp::vm::test {

template <typename T>
std::uint64_t bits(T value) {
    std::uint64_t raw = 0;
    std::memcpy(&raw, &value, sizeof(T));
    return raw;
}

class Harness {
public:
    static constexpr std::uint32_t kInstanceSize = 512;

    Harness() {
        main = builder.declare_pou("Main", PouKind::Program, kInstanceSize);
        instance = builder.allocate(kInstanceSize, 8);
        builder.begin_body(main);
    }

    /// Ends Main's body (the test emitted its Ret).
    void end_main(std::uint32_t frame_size = 64, std::uint32_t out_size = 64) {
        builder.end_body(frame_size, out_size);
    }

    /// Adds the task running Main, finishes, links and prepares the machine. Empty on success.
    std::string load(std::uint32_t stack_size = 4096) {
        builder.task(Task{.name = "MainTask",
                          .kind = TaskKind::Cyclic,
                          .interval_ns = 1'000'000,
                          .stack_size = stack_size,
                          .entries = {TaskEntry{main, instance}}});
        auto image = builder.finish();
        if (!image) {
            return image.error();
        }
        auto linked = link(std::move(*image), natives);
        if (!linked) {
            return linked.error();
        }
        program.emplace(std::move(*linked));
        machine.emplace(*program);
        return {};
    }

    /// load() then one cycle of the task.
    RunState run() {
        if (auto error = load(); !error.empty()) {
            ADD_FAILURE() << error;
            return RunState::Idle;
        }
        return machine->run_cycle(0);
    }

    template <typename T>
    T get(std::uint32_t self_offset) const {
        T value;
        std::memcpy(&value, machine->memory().data() + instance + self_offset, sizeof(T));
        return value;
    }
    template <typename T>
    void set(std::uint32_t self_offset, T value) {
        std::memcpy(machine->memory().data() + instance + self_offset, &value, sizeof(T));
    }
    /// Initial value of a Main variable, before load().
    template <typename T>
    void init(std::uint32_t self_offset, T value) {
        std::uint8_t raw[sizeof(T)];
        std::memcpy(raw, &value, sizeof(T));
        builder.initialise(instance + self_offset, raw);
    }

    Builder builder;
    NativeRegistry natives;
    std::uint32_t main = 0;
    std::uint32_t instance = 0;
    std::optional<Program> program;
    std::optional<Machine> machine;
};

inline Operand self(std::uint32_t offset) {
    return Operand::self(offset);
}
inline Operand imm(std::int32_t value) {
    return Operand::imm(static_cast<std::uint32_t>(value));
}

} // namespace eposp::vm::test
