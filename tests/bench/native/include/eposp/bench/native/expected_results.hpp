#pragma once

// The correct globals after exactly 1000 scans, from the table in ../shared/bench/README.md:
// every correct IEC 61131-3 implementation (native translation or VM) must reproduce them.

#include <array>
#include <cstdint>
#include <string_view>

namespace eposp::bench::native {

inline constexpr std::int32_t kCheckedScans = 1000;

struct ExpectedResult {
    std::string_view program;
    std::int32_t cycles;
    std::int32_t result;
    double r; // compared to 6 decimals
};

inline constexpr std::array kExpectedAfter1000Scans{
    ExpectedResult{"bubble_sort", 1000, 83864152, 83864.152000},
    ExpectedResult{"sieve", 1000, 1027, 1027142.000000},
    ExpectedResult{"crc32", 1000, 1099718708, 514947.000000},
    ExpectedResult{"pid_plant", 1000, 736487, 736.486794},
    ExpectedResult{"conveyor_fsm", 1000, 22607, 356707.000000},
    ExpectedResult{"fb_channels", 1000, 14696, 0.000000},
    ExpectedResult{"strings", 1000, 673161, 673.161000},
};

} // namespace eposp::bench::native
