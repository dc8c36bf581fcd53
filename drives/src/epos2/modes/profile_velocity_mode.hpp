#pragma once

#include "eposp/drives/motion/profile_velocity_generator.hpp"
#include "eposp/drives/motion/target_reached_monitor.hpp"
#include "mode_behaviour.hpp"

namespace eposp::drives::epos2 {

/// Profile Velocity Mode (EPOS2 FW spec 5.10): ramps to Target Velocity 0x60FF; controlword bit
/// 8 halt; statusword bits 10 target reached and 12 speed is equal 0.
class ProfileVelocityMode final : public ModeBehaviour {
public:
    explicit ProfileVelocityMode(ModeServices& services) : services_(services) {}

    void start(double now, std::int64_t position, bool power_stage_on) override;
    void on_controlword(const ControlwordChange& change) override;
    void on_set_value_written(double now, std::uint16_t index, std::uint8_t sub_index) override;
    ModeDemand demand(const ModeInputs& inputs) override;
    void watch(const ModeInputs& inputs, const motion::MotionState& demand) override;
    std::uint16_t statusword_bits(double now, bool following_error) const override;
    void stop_completed(double position) override { profile_.reset(position); }

private:
    void follow_target(double now);

    ModeServices& services_;
    motion::ProfileVelocityGenerator profile_;
    motion::TargetReachedMonitor target_reached_{{}};
    bool target_reached_now_ = false; ///< statusword bit 10, this period
    bool standstill_now_ = false;     ///< statusword bit 12
};

} // namespace eposp::drives::epos2
