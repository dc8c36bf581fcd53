#pragma once

#include "eposp/drives/motion/profile_position_generator.hpp"
#include "eposp/drives/motion/target_reached_monitor.hpp"
#include "mode_behaviour.hpp"

namespace eposp::drives::epos2 {

/// Profile Position Mode (EPOS2 FW spec 5.3): targets 0x607A by controlword bit 4 with bits 5, 6,
/// 8 and 15; statusword bits 10 target reached, 12 set-point acknowledge, 13 following error.
class ProfilePositionMode final : public ModeBehaviour {
public:
    explicit ProfilePositionMode(ModeServices& services) : services_(services) {}

    void start(double now, std::int64_t position, bool power_stage_on) override;
    void on_controlword(const ControlwordChange& change) override;
    ModeDemand demand(const ModeInputs& inputs) override;
    void watch(const ModeInputs& inputs, const motion::MotionState& demand) override;
    std::uint16_t statusword_bits(double now, bool following_error) const override;
    void stop_completed(double position) override { profile_.reset(position); }

private:
    bool new_setpoint(double now, std::uint16_t controlword);

    ModeServices& services_;
    motion::ProfilePositionGenerator profile_;
    motion::TargetReachedMonitor target_reached_{{}};
    bool setpoint_acknowledged_ = false; ///< statusword bit 12
    bool target_reached_now_ = false;    ///< statusword bit 10, this period
};

} // namespace eposp::drives::epos2
