#pragma once

#include "eposp/drives/motion/position_set_value_limiter.hpp"
#include "mode_behaviour.hpp"

namespace eposp::drives::epos2 {

/// Position Mode (EPOS2 FW spec 5.6): Position Mode Setting Value 0x2062, or the analog position
/// set value (0x2303), is the position demand of the position loop, limited by the software
/// position limits 0x607D, Maximal Profile Velocity 0x607F and Max Acceleration 0x60C5 (table
/// 5-37). The following error (0x6065) is watched. Table 8-114 gives the mode no statusword bits
/// and table 8-113 no controlword bits (no halt).
class PositionMode final : public ModeBehaviour {
public:
    explicit PositionMode(ModeServices& services) : services_(services) {}

    void start(double now, std::int64_t position, bool power_stage_on) override;
    void on_controlword(const ControlwordChange&) override {}
    ModeDemand demand(const ModeInputs& inputs) override;
    std::uint16_t statusword_bits(double, bool) const override { return 0; }
    void stop_completed(double position) override {
        limiter_ = motion::PositionSetValueLimiter(position);
    }

private:
    double set_value() const;

    ModeServices& services_;
    motion::PositionSetValueLimiter limiter_;
};

} // namespace eposp::drives::epos2
