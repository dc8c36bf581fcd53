// Translation of ../shared/bench/pid_plant.st.

#include "eposp/bench/native/iec_arith.hpp"
#include "translations.hpp"

#include <cmath>
#include <cstdint>

namespace eposp::bench::native {
namespace {

struct PidCtl {
    double sp = 0, pv = 0, kp = 0, ki = 0, kd = 0, tsample = 0, lo = 0, hi = 0; // VAR_INPUT
    double cv = 0;                                                              // VAR_OUTPUT
    double integ = 0, prev_err = 0, err = 0, deriv = 0;

    void run() {
        err = sp - pv;
        integ = limit(lo, integ + ki * err * tsample, hi);
        deriv = (err - prev_err) / tsample;
        prev_err = err;
        cv = limit(lo, kp * err + integ + kd * deriv, hi);
    }
};

struct SecondOrderPlant {
    double force = 0, tsample = 0; // VAR_INPUT
    double y = 0;                  // VAR_OUTPUT
    double v = 0;

    void run() {
        v = v + (force - 0.8 * v - 2.0 * y) * tsample;
        y = y + v * tsample;
    }
};

class Main final : public Program {
public:
    void scan(core::TimePoint /*now*/) override {
        auto& [result, cycles, r] = globals_;
        cycles = wrap_add(cycles, 1);
        if (cycles % 2 == 0) {
            sp = 1.0;
        } else {
            sp = -0.5;
        }
        err_sum = 0.0;
        for (k = 1; k <= 2000; ++k) {
            ctrl.sp = sp;
            ctrl.pv = plant1.y;
            ctrl.kp = 4.0;
            ctrl.ki = 2.0;
            ctrl.kd = 0.05;
            ctrl.tsample = 0.001;
            ctrl.lo = -10.0;
            ctrl.hi = 10.0;
            ctrl.run();
            plant1.force = ctrl.cv;
            plant1.tsample = 0.001;
            plant1.run();
            err_sum = err_sum + std::abs(sp - plant1.y);
        }
        r = err_sum;
        result = lreal_to_dint(err_sum * 1000.0);
    }

private:
    PidCtl ctrl;
    SecondOrderPlant plant1;
    std::int16_t k = 0;
    double sp = 0, err_sum = 0;
};

} // namespace

std::unique_ptr<Program> make_pid_plant() {
    return std::make_unique<Main>();
}

} // namespace eposp::bench::native
