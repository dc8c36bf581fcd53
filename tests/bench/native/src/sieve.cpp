// Translation of ../shared/bench/sieve.st.

#include "eposp/bench/native/iec_arith.hpp"
#include "translations.hpp"

#include <array>
#include <cstdint>

namespace eposp::bench::native {
namespace {

// A FUNCTION has no memory: its VARs, the flag array included, start from their initial
// values at every call (IEC 61131-3: functions have no memory).
std::int32_t count_primes(std::int32_t upto) {
    std::array<bool, 8192> flags{};
    std::int32_t i = 0, k = 0, n = 0;
    for (i = 0; i <= upto; ++i) {
        flags[i] = true;
    }
    flags[0] = false;
    flags[1] = false;
    i = 2;
    while (wrap_mul(i, i) <= upto) {
        if (flags[i]) {
            k = wrap_mul(i, i);
            while (k <= upto) {
                flags[k] = false;
                k = wrap_add(k, i);
            }
        }
        i = wrap_add(i, 1);
    }
    n = 0;
    for (i = 0; i <= upto; ++i) {
        if (flags[i]) {
            n = wrap_add(n, 1);
        }
    }
    return n;
}

class Main final : public Program {
public:
    void scan(core::TimePoint /*now*/) override {
        auto& [result, cycles, r] = globals_;
        cycles = wrap_add(cycles, 1);
        result = count_primes(wrap_sub(8191, cycles % 7));
        r = r + static_cast<double>(result);
    }
};

} // namespace

std::unique_ptr<Program> make_sieve() {
    return std::make_unique<Main>();
}

} // namespace eposp::bench::native
