// Translation of ../shared/bench/conveyor_fsm.st.

#include "eposp/bench/native/iec_arith.hpp"
#include "translations.hpp"

#include <array>
#include <cstdint>

namespace eposp::bench::native {
namespace {

enum class StationState { Idle, Loading, Moving, Unloading, Faulted };

struct Item {
    StationState state = StationState::Idle;
    std::int32_t pos = 0;
    std::int32_t target = 0;
    std::int16_t weight = 0;
    std::uint32_t done = 0;
};

struct Line {
    std::int32_t tick = 0;      // VAR_INPUT
    std::int32_t moved = 0;     // VAR_OUTPUT
    std::uint32_t finished = 0; // VAR_OUTPUT
    std::array<Item, 512> items{};
    std::int16_t i = 0;

    void operator()(std::int32_t tick_in) {
        tick = tick_in;
        moved = 0;
        for (i = 0; i <= 511; ++i) {
            Item& item = items[i];
            switch (item.state) {
            case StationState::Idle:
                if (wrap_add(tick, std::int32_t{i}) % 5 == 0) {
                    item.state = StationState::Loading;
                    item.weight = static_cast<std::int16_t>((i * 7) % 97);
                }
                break;
            case StationState::Loading:
                item.target = wrap_add(wrap_add(item.pos, 10), std::int32_t{item.weight % 13});
                item.state = StationState::Moving;
                break;
            case StationState::Moving:
                if (item.pos < item.target) {
                    item.pos = wrap_add(item.pos, 1);
                    moved = wrap_add(moved, 1);
                } else {
                    item.state = StationState::Unloading;
                }
                break;
            case StationState::Unloading:
                if (item.weight > 90) {
                    item.state = StationState::Faulted;
                } else {
                    item.done = item.done + 1;
                    item.state = StationState::Idle;
                }
                break;
            case StationState::Faulted:
                if (wrap_add(tick, std::int32_t{i}) % 50 == 0) {
                    item.state = StationState::Idle;
                    item.weight = 0;
                }
                break;
            }
        }
        finished = 0;
        for (i = 0; i <= 511; ++i) {
            finished = finished + items[i].done;
        }
    }
};

class Main final : public Program {
public:
    void scan(core::TimePoint /*now*/) override {
        auto& [result, cycles, r] = globals_;
        cycles = wrap_add(cycles, 1);
        l(cycles);
        result = static_cast<std::int32_t>(l.finished);
        r = r + static_cast<double>(l.moved);
    }

private:
    Line l;
};

} // namespace

std::unique_ptr<Program> make_conveyor_fsm() {
    return std::make_unique<Main>();
}

} // namespace eposp::bench::native
