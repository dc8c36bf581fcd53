// Translation of ../shared/bench/bubble_sort.st.

#include "eposp/bench/native/iec_arith.hpp"
#include "translations.hpp"

#include <array>
#include <cstdint>

namespace eposp::bench::native {
namespace {

struct Sorter {
    std::int32_t seed = 0;     // VAR_INPUT
    std::int32_t checksum = 0; // VAR_OUTPUT
    std::array<std::int32_t, 256> a{};
    std::int32_t i = 0, j = 0, t = 0, x = 0;

    void operator()(std::int32_t seed_in) {
        seed = seed_in;
        x = seed;
        for (i = 0; i <= 255; ++i) {
            x = wrap_add(wrap_mul(x, 75), 74) % 65537;
            if (x < 0) {
                x = wrap_neg(x);
            }
            a[i] = x % 10000;
        }
        for (i = 0; i <= 254; ++i) {
            for (j = 0; j <= 254 - i; ++j) {
                if (a[j] > a[j + 1]) {
                    t = a[j];
                    a[j] = a[j + 1];
                    a[j + 1] = t;
                }
            }
        }
        checksum = wrap_add(wrap_add(a[0], wrap_mul(a[128], 3)), wrap_mul(a[255], 7));
    }
};

class Main final : public Program {
public:
    void scan(core::TimePoint /*now*/) override {
        auto& [result, cycles, r] = globals_;
        cycles = wrap_add(cycles, 1);
        s(cycles);
        result = wrap_add(result, s.checksum);
        r = static_cast<double>(result) / static_cast<double>(cycles);
    }

private:
    Sorter s;
};

} // namespace

std::unique_ptr<Program> make_bubble_sort() {
    return std::make_unique<Main>();
}

} // namespace eposp::bench::native
