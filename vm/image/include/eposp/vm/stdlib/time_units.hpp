#pragma once

#include <cstdint>

namespace eposp::vm::stdlib {

// TIME, LTIME, DATE, TOD and DT are nanosecond counts (vm/README.md, "Standard library").
inline constexpr std::int64_t kNsPerUs = 1'000;
inline constexpr std::int64_t kNsPerMs = 1'000'000;
inline constexpr std::int64_t kNsPerS = 1'000'000'000;
inline constexpr std::int64_t kNsPerMin = 60 * kNsPerS;
inline constexpr std::int64_t kNsPerH = 60 * kNsPerMin;
inline constexpr std::int64_t kNsPerDay = 24 * kNsPerH;

} // namespace eposp::vm::stdlib
