#pragma once

// The IEC 61131-3 standard function blocks the benchmark programs call (3rd edition, 6.6.3.5),
// written as a competent engineer would write them for a PLC runtime. Each call takes its
// inputs like an ST call and updates the outputs; TON reads the task's virtual clock.

#include "eposp/core/time.hpp"

#include <cstdint>
#include <limits>

namespace eposp::bench::native {

using Time = core::Duration; // IEC TIME

// IEC 61131-3 6.6.3.5.3: R_TRIG, Q is TRUE for one call after CLK rises.
struct RTrig {
    bool q = false;
    bool m = false;

    void operator()(bool clk) {
        q = clk && !m;
        m = clk;
    }
};

// IEC 61131-3 6.6.3.5.4: CTU, counts rising edges of CU up to the INT maximum; R has priority.
struct Ctu {
    bool q = false;
    std::int16_t cv = 0;
    RTrig cu_edge;

    void operator()(bool cu, bool r, std::int16_t pv) {
        cu_edge(cu);
        if (r) {
            cv = 0;
        } else if (cu_edge.q && cv < std::numeric_limits<std::int16_t>::max()) {
            cv = static_cast<std::int16_t>(cv + 1);
        }
        q = cv >= pv;
    }
};

// IEC 61131-3 6.6.3.5.2: SR, set-dominant bistable.
struct Sr {
    bool q1 = false;

    void operator()(bool s1, bool r) { q1 = s1 || (!r && q1); }
};

// IEC 61131-3 6.6.3.5.5: TON. ET counts from the call that sees IN rise; Q once ET reaches PT.
struct Ton {
    bool q = false;
    Time et{0};
    bool running = false;
    core::TimePoint start{};

    void operator()(bool in, Time pt, core::TimePoint now) {
        if (!in) {
            q = false;
            et = Time{0};
            running = false;
            return;
        }
        if (!running) {
            running = true;
            start = now;
        }
        const Time elapsed = now - start;
        q = elapsed >= pt;
        et = q ? pt : elapsed;
    }
};

} // namespace eposp::bench::native
