// Translation of ../shared/bench/crc32.st.

#include "eposp/bench/native/iec_arith.hpp"
#include "translations.hpp"

#include <array>
#include <cstdint>

namespace eposp::bench::native {
namespace {

struct Crc32 {
    std::int32_t seed = 0; // VAR_INPUT
    std::uint32_t crc = 0; // VAR_OUTPUT
    std::array<std::uint8_t, 1024> buf{};
    std::int16_t i = 0, b = 0;
    std::uint32_t c = 0;
    std::int32_t x = 0;

    void operator()(std::int32_t seed_in) {
        seed = seed_in;
        x = seed;
        for (i = 0; i <= 1023; ++i) {
            x = wrap_add(wrap_mul(x, 1103), 12345) % 32749;
            buf[i] = static_cast<std::uint8_t>(x); // DINT_TO_BYTE keeps the low 8 bits
        }
        c = 0xFFFFFFFFu;
        for (i = 0; i <= 1023; ++i) {
            c = c ^ static_cast<std::uint32_t>(buf[i]);
            for (b = 1; b <= 8; ++b) {
                if ((c & 0x00000001u) != 0) {
                    c = (c >> 1) ^ 0xEDB88320u;
                } else {
                    c = c >> 1;
                }
            }
        }
        crc = c ^ 0xFFFFFFFFu;
    }
};

class Main final : public Program {
public:
    void scan(core::TimePoint /*now*/) override {
        auto& [result, cycles, r] = globals_;
        cycles = wrap_add(cycles, 1);
        f(cycles);
        result = static_cast<std::int32_t>(f.crc & 0x7FFFFFFFu);
        r = r + static_cast<double>(result % 1000);
    }

private:
    Crc32 f;
};

} // namespace

std::unique_ptr<Program> make_crc32() {
    return std::make_unique<Main>();
}

} // namespace eposp::bench::native
