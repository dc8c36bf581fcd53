#pragma once

#include "mode_behaviour.hpp"

namespace eposp::drives::epos2 {

/// Diagnostic Mode (-4; EPOS2 FW spec 5.2: "Only used for the Diagnostic Wizard of the Graphical
/// User Interface"; 0x6502 bit 19). maxon documents no set value, parameter or behaviour for it,
/// so the simulation gives it none: the power stage stays on and the current loop holds zero
/// current, the motor coasts (friction alone slows it) and stays where it is put. The safe choice:
/// a program that selects the mode moves nothing. No position loop runs, so no following error;
/// tables 8-113 and 8-114 give the mode no controlword or statusword bits.
class DiagnosticMode final : public ModeBehaviour {
public:
    void start(double, std::int64_t, bool) override {}
    void on_controlword(const ControlwordChange&) override {}
    ModeDemand demand(const ModeInputs& inputs) override;
    std::uint16_t statusword_bits(double, bool) const override { return 0; }
    void stop_completed(double) override {}
    bool position_controlled() const override { return false; }
};

} // namespace eposp::drives::epos2
