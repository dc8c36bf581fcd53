#pragma once

namespace eposp::drives::motion {

/// The share of its processor a drive's tasks would take (1: all of it). The simulated firmware
/// never runs short of processor time itself, so the load is a cause set from outside, as the
/// supply voltage is; each drive decides what its firmware does when it runs short (the ESCON2's
/// SystemLoadSupervision, the EPOS2's System Overloaded Error 0xFF0B). The manuals give no
/// thresholds; the simulation's are kCritical and 1.
class SystemLoad {
public:
    static constexpr double kCritical = 0.9;

    void set(double share) { share_ = share; }
    /// Near the limit: the ESCON2 warns.
    bool critical() const { return share_ >= kCritical; }
    /// Beyond what the processor has: the firmware misses its work.
    bool overloaded() const { return share_ > 1; }

private:
    double share_ = 0;
};

} // namespace eposp::drives::motion
