#pragma once

// The limits of a program image, stated once: the loader (verifier.cpp) refuses an image beyond
// them and the compiler refuses, with the limit in its message, a program that would need more,
// so that what `eposp build` accepts `eposp run` loads. docs/st-language.md lists them.

#include <cstdint>

namespace eposp::vm {

/// The largest static data area (globals, program and FB instances), task stack, frame and
/// instance an image may ask for.
inline constexpr std::uint32_t kMaxAreaSize = 64U << 20;

/// How deep calls that are not inlined may nest in a task before it stops with a stack overflow.
inline constexpr std::uint32_t kMaxCallDepth = 256;

/// The shortest interval of a cyclic task: the EPOS P runs its timer tasks on a 1 ms tick, as
/// CODESYS does (a shorter INTERVAL only simulates cycles no controller runs).
inline constexpr std::uint64_t kMinTaskIntervalNs = 1'000'000;

} // namespace eposp::vm
