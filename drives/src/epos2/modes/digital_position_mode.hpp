#pragma once

#include "eposp/drives/motion/position_set_value_limiter.hpp"
#include "mode_behaviour.hpp"

namespace eposp::drives::epos2 {

/// Master Encoder Mode (-5) and Step/Direction Mode (-6), EPOS2 FW spec 5.7, 5.8, 8.2.80: the
/// counter of digital inputs 2 and 3 (a quadrature counter of a master encoder, or an up/down
/// counter of step pulses) is the Digital Position Desired Value 0x2300 sub 1 (negated with
/// polarity 1); times Numerator / Denominator (sub 2 / 3) plus the Offset (sub 5) it is the
/// position demand, limited by 0x607D, 0x607F and 0x60C5 (tables 5-40, 5-43): an electronic gear.
/// A denominator of 0 holds the demand. The modes own no statusword or controlword bits.
class DigitalPositionMode final : public ModeBehaviour {
public:
    explicit DigitalPositionMode(ModeServices& services) : services_(services) {}

    void start(double now, std::int64_t position, bool power_stage_on) override;
    void on_controlword(const ControlwordChange&) override {}
    ModeDemand demand(const ModeInputs& inputs) override;
    std::uint16_t statusword_bits(double, bool) const override { return 0; }
    void stop_completed(double position) override;

private:
    ModeServices& services_;
    motion::PositionSetValueLimiter limiter_;
    double held_ = 0; ///< the set value while the denominator is 0
};

} // namespace eposp::drives::epos2
