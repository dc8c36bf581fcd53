// Translation of ../shared/bench/fb_channels.st.

#include "eposp/bench/native/iec_arith.hpp"
#include "eposp/bench/native/standard_fbs.hpp"
#include "translations.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace eposp::bench::native {
namespace {

struct Channel {
    bool input = false;     // VAR_INPUT
    Time preset{0};         // VAR_INPUT
    std::int16_t count = 0; // VAR_OUTPUT
    bool latched = false;   // VAR_OUTPUT
    Ton debounce;
    RTrig edge;
    Ctu counter;
    Sr latch;

    void operator()(bool input_in, Time preset_in, core::TimePoint now) {
        input = input_in;
        preset = preset_in;
        debounce(input, preset, now);
        edge(debounce.q);
        counter(edge.q, counter.q, 1000);
        latch(counter.cv > 500, !input && counter.cv < 10);
        count = counter.cv;
        latched = latch.q1;
    }
};

constexpr std::size_t kChannels = 200;

class Main final : public Program {
public:
    void scan(core::TimePoint now) override {
        auto& [result, cycles, r] = globals_;
        cycles = wrap_add(cycles, 1);
        total = 0;
        nlatched = 0;
        call_channels(now, std::make_index_sequence<kChannels>{});
        result = total;
        r = r + static_cast<double>(nlatched);
    }

private:
    // The ST spells out 200 calls ch<K>(input := ((cycles + K) MOD (3 + K MOD 5)) < 2,
    // preset := T#(1 + K MOD 3)ms); this expands to the same 200 calls with literal constants.
    template <std::size_t... K>
    void call_channels(core::TimePoint now, std::index_sequence<K...> /*unused*/) {
        (call_channel<K>(now), ...);
    }

    template <std::size_t K>
    void call_channel(core::TimePoint now) {
        constexpr auto kOffset = static_cast<std::int32_t>(K);
        constexpr auto kModulus = static_cast<std::int32_t>(3 + K % 5);
        constexpr Time kPreset = std::chrono::milliseconds(1 + K % 3);
        Channel& ch = ch_[K];
        ch(wrap_add(globals_.cycles, kOffset) % kModulus < 2, kPreset, now);
        total = wrap_add(total, std::int32_t{ch.count});
        if (ch.latched) {
            nlatched = wrap_add(nlatched, 1);
        }
    }

    std::array<Channel, kChannels> ch_{}; // ch0 .. ch199
    std::int32_t total = 0, nlatched = 0;
};

} // namespace

std::unique_ptr<Program> make_fb_channels() {
    return std::make_unique<Main>();
}

} // namespace eposp::bench::native
