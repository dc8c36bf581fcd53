// Translation of ../shared/bench/strings.st.

#include "eposp/bench/native/iec_arith.hpp"
#include "eposp/bench/native/iec_string.hpp"
#include "translations.hpp"

#include <cstdint>

namespace eposp::bench::native {
namespace {

struct Telegram {
    std::int16_t n = 0;        // VAR_INPUT
    std::int32_t checksum = 0; // VAR_OUTPUT
    String s, part;
    std::int16_t i = 0, p = 0;

    void operator()(std::int16_t n_in) {
        n = n_in;
        checksum = 0;
        for (i = 1; i <= 40; ++i) {
            // INT operands are promoted to 32 bits and narrowed when passed (iec_arith.hpp).
            s = concat("ID=", int_to_string(static_cast<std::int16_t>(n + i)));
            s = concat(s, ";POS=");
            // n * i exceeds 32767 once n > 819: the product is not wrapped to 16 bits.
            s = concat(s, int_to_string(static_cast<std::int16_t>((n * i) % 1000)));
            p = find(s, ";");
            part = mid(s, static_cast<std::int16_t>(len(s) - p), static_cast<std::int16_t>(p + 1));
            checksum =
                wrap_add(wrap_add(wrap_add(checksum, std::int32_t{len(part)}), std::int32_t{p}),
                         std::int32_t{len(left(s, 3))});
        }
    }
};

class Main final : public Program {
public:
    void scan(core::TimePoint /*now*/) override {
        auto& [result, cycles, r] = globals_;
        cycles = wrap_add(cycles, 1);
        t(static_cast<std::int16_t>(cycles % 20000)); // DINT_TO_INT
        result = wrap_add(result, t.checksum);
        r = static_cast<double>(result) / 1000.0;
    }

private:
    Telegram t;
};

} // namespace

std::unique_ptr<Program> make_strings() {
    return std::make_unique<Main>();
}

} // namespace eposp::bench::native
