#pragma once

// What a fuzz target asserts beyond "no crash": a property every input must keep. A broken one
// aborts, which libFuzzer and the replay driver both report as a failing input.

#include <cstdio>
#include <cstdlib>

namespace eposp::fuzz {

inline void require(bool holds, const char* property) {
    if (!holds) {
        std::fprintf(stderr, "fuzz property broken: %s\n", property);
        std::abort();
    }
}

} // namespace eposp::fuzz
