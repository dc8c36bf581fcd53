#pragma once

#include "eposp/drives/plant/shaft_sensors.hpp"

#include <array>
#include <cstdint>

namespace eposp::drives::epos2 {

/// EPOS2 FW spec tables 8-86 / 8-87: the input functionalities by their bit in 0x2071 (6 … 15
/// are the general purpose inputs J … A).
enum class InputFunction : std::uint8_t {
    NegativeLimitSwitch = 0,
    PositiveLimitSwitch = 1,
    HomeSwitch = 2,
    PositionMarker = 3,
    DeviceEnable = 4,
    QuickStop = 5,
};

constexpr std::uint16_t function_bit(InputFunction function) {
    return static_cast<std::uint16_t>(1U << static_cast<unsigned>(function));
}

/// Table 8-85: an EPOS2 24/5 has six digital inputs.
inline constexpr unsigned kDigitalInputCount = 6;

/// 0x2070 sub 1 … 6 and 0x2071 sub 2 … 4 with their defaults (tables 8-85, 8-88, 8-89).
struct DigitalInputConfiguration {
    std::array<std::uint16_t, kDigitalInputCount> functions{15, 14, 13, 2, 1, 0};
    std::uint16_t mask = 0xE007;
    std::uint16_t polarity = 0;
    std::uint16_t execution_mask = 0x0008;
};

/// The rising and falling edges of functionality states between two samples.
struct InputEdges {
    std::uint16_t rising = 0;
    std::uint16_t falling = 0;
};

/// Remembers the last states and reports what changed.
class EdgeDetector {
public:
    InputEdges update(std::uint16_t states) {
        const InputEdges edges{.rising = static_cast<std::uint16_t>(states & ~before_),
                               .falling = static_cast<std::uint16_t>(before_ & ~states)};
        before_ = states;
        return edges;
    }

private:
    std::uint16_t before_ = 0;
};

/// The digital input pins of an EPOS2 24/5 and the functionalities they carry (8.2.56, 8.2.57).
/// A pin is high when an outside source drives it high (a test, the network file, an EPOS P
/// output) or when the machine's switch wired to it is pressed. The machine's switches are
/// normally open contacts wired as table 8-85's defaults for the 24/5 assign them: the home
/// switch to input 4, the positive limit switch to input 5, the negative one to input 6.
class DigitalInputs {
public:
    /// Pin `input` (1 … 6) driven high or low from outside; the other sources still apply.
    void set_level(unsigned input, bool high);
    /// A limit switch held pressed whatever the position (fault injection), or let go.
    void hold_limit_switch(InputFunction which, bool pressed);
    DigitalInputs() { configure({}); }
    void configure(const DigitalInputConfiguration& config);
    const DigitalInputConfiguration& configuration() const { return config_; }

    /// The pins' levels, bit n-1 for input n, with the machine's switches as `machine` says.
    /// Inline, as states(): the drive reads its inputs several times each control period.
    std::uint8_t levels(const plant::SwitchStates& machine) const {
        // Table 8-85, column EPOS2 24/5: where the machine's switches are wired (bit n-1 =
        // input n).
        constexpr std::uint8_t kHomeSwitchPin = 1U << 3;
        constexpr std::uint8_t kPositiveLimitPin = 1U << 4;
        constexpr std::uint8_t kNegativeLimitPin = 1U << 5;
        std::uint8_t levels = outside_;
        if (machine.home) {
            levels |= kHomeSwitchPin;
        }
        if (machine.positive_limit || held_.positive_limit) {
            levels |= kPositiveLimitPin;
        }
        if (machine.negative_limit || held_.negative_limit) {
            levels |= kNegativeLimitPin;
        }
        return levels;
    }
    /// The functionality states after the polarity (table 8-88): a pin carries the functionality
    /// 0x2070 assigns it, active when its level is the active one. The mask does not act here: it
    /// only filters the display (8.2.57), while the execution mask decides what is executed.
    std::uint16_t states(const plant::SwitchStates& machine) const {
        return states_by_levels_[levels(machine)];
    }
    /// 0x2071 sub 1: the states under the mask.
    std::uint16_t displayed(const plant::SwitchStates& machine) const {
        return states(machine) & config_.mask;
    }

private:
    DigitalInputConfiguration config_;
    /// states() for each of the 64 pin levels, made when configured: the drive asks for the
    /// states several times each control period.
    std::array<std::uint16_t, std::size_t{1} << kDigitalInputCount> states_by_levels_{};
    std::uint8_t outside_ = 0;
    plant::SwitchStates held_;
};

} // namespace eposp::drives::epos2
