#pragma once

#include "mode_behaviour.hpp"

namespace eposp::drives::epos2 {

/// Homing Mode (EPOS2 FW spec 5.4): controlword bit 4 starts the method of 0x6098, bit 8 halts;
/// statusword bits 10 target reached, 12 homing attained, 13 homing error. The procedure is the
/// drive's (ModeServices::homing), so that the reference outlives the mode.
class HomingMode final : public ModeBehaviour {
public:
    explicit HomingMode(ModeServices& services) : services_(services) {}

    void start(double now, std::int64_t position, bool power_stage_on) override;
    void on_controlword(const ControlwordChange& change) override;
    ModeDemand demand(const ModeInputs& inputs) override;
    std::uint16_t statusword_bits(double now, bool following_error) const override;
    void drive_disabled(double now) override;
    void stop_completed(double position) override { services_.homing.reset(position); }
    bool supervises_limits() const override { return false; }

private:
    motion::HomingParameters parameters() const;

    ModeServices& services_;
};

} // namespace eposp::drives::epos2
