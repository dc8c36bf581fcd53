#include "eposp/bench/native/program.hpp"
#include "translations.hpp"

#include <array>

namespace eposp::bench::native {

std::span<const ProgramEntry> programs() {
    static constexpr std::array kPrograms{
        ProgramEntry{"bubble_sort", make_bubble_sort},
        ProgramEntry{"sieve", make_sieve},
        ProgramEntry{"crc32", make_crc32},
        ProgramEntry{"pid_plant", make_pid_plant},
        ProgramEntry{"conveyor_fsm", make_conveyor_fsm},
        ProgramEntry{"fb_channels", make_fb_channels},
        ProgramEntry{"strings", make_strings},
    };
    return kPrograms;
}

void run_scans(Program& program, std::int32_t scans, core::TimePoint first) {
    for (std::int32_t i = 0; i < scans; ++i) {
        program.scan(first + i * kScanInterval);
    }
}

} // namespace eposp::bench::native
