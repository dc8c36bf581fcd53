#pragma once

// The native (hand-translated C++) side of the VM benchmark: every program of
// ../shared/bench/*.st behind one interface, so that a runner can time a native scan and a VM
// scan of the same program by name in the same run.

#include "eposp/core/time.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

namespace eposp::bench::native {

// VAR_GLOBAL of CONFIGURATION Config0, common to all seven programs.
struct Globals {
    std::int32_t result = 0; // DINT
    std::int32_t cycles = 0; // DINT
    double r = 0.0;          // LREAL
};

// One PROGRAM instance with its globals, in its initial state after construction.
class Program {
public:
    virtual ~Program() = default;

    // One execution of the 1 ms task; `now` is the virtual clock that TON reads.
    virtual void scan(core::TimePoint now) = 0;

    const Globals& globals() const { return globals_; }

protected:
    Globals globals_;
};

// A benchmark program: its name is the .st file name without extension.
struct ProgramEntry {
    std::string_view name;
    std::unique_ptr<Program> (*make)();
};

std::span<const ProgramEntry> programs();

// The task interval of every program: the virtual clock advances this much per scan.
inline constexpr core::Duration kScanInterval = std::chrono::milliseconds(1);

// Runs `scans` scans from the program's current state, the clock starting at `first`.
void run_scans(Program& program, std::int32_t scans, core::TimePoint first = core::TimePoint{});

} // namespace eposp::bench::native
