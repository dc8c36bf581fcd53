#pragma once

#include "mode_behaviour.hpp"

namespace eposp::drives::epos2 {

/// Velocity Mode (EPOS2 FW spec 5.11): Velocity Mode Setting Value 0x206B, or the analog
/// velocity set value (0x2302), is the demand of the velocity loop (5.12), within Maximal
/// Profile Velocity 0x607F and changing at most at Max Acceleration 0x60C5 (table 5-55). No
/// position loop runs, so no following error. Table 8-114 gives the mode no statusword bits and
/// table 8-113 no controlword bits (no halt).
class VelocityMode final : public ModeBehaviour {
public:
    explicit VelocityMode(ModeServices& services) : services_(services) {}

    void start(double now, std::int64_t position, bool power_stage_on) override;
    void on_controlword(const ControlwordChange&) override {}
    ModeDemand demand(const ModeInputs& inputs) override;
    std::uint16_t statusword_bits(double, bool) const override { return 0; }
    void stop_completed(double) override { velocity_ = 0; }
    bool position_controlled() const override { return false; }

private:
    ModeServices& services_;
    double velocity_ = 0; ///< the demand, quadcounts/s
};

} // namespace eposp::drives::epos2
