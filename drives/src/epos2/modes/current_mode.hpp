#pragma once

#include "mode_behaviour.hpp"

namespace eposp::drives::epos2 {

/// Current Mode (EPOS2 FW spec 5.13): Current Mode Setting Value 0x2030, or the analog current
/// set value (0x2301), is the demand of the current loop (5.14), within ± Output Current Limit
/// 0x6410 sub 2 (8.2.50), the speed kept below Maximal Motor Speed 0x6410 sub 4 by the velocity
/// controller (8.2.130). No position loop runs, so no following error. Table 8-114 gives the mode
/// no statusword bits and table 8-113 no controlword bits (no halt).
class CurrentMode final : public ModeBehaviour {
public:
    explicit CurrentMode(ModeServices& services) : services_(services) {}

    void start(double, std::int64_t, bool) override {}
    void on_controlword(const ControlwordChange&) override {}
    ModeDemand demand(const ModeInputs& inputs) override;
    std::uint16_t statusword_bits(double, bool) const override { return 0; }
    void stop_completed(double) override {}
    bool position_controlled() const override { return false; }

private:
    ModeServices& services_;
};

} // namespace eposp::drives::epos2
