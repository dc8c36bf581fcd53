#pragma once

#include <array>
#include <cstdint>
#include <optional>

namespace eposp::drives::epos2 {

/// EPOS2 FW spec tables 8-92 / 8-94: the output functionalities the firmware drives, by their bit
/// in 0x2078 (8 … 15 are the general purpose outputs H … A, written by the master).
enum class OutputFunction : std::uint8_t { ReadyFault = 0, PositionCompare = 1, HoldingBrake = 2 };

constexpr std::uint16_t function_bit(OutputFunction function) {
    return static_cast<std::uint16_t>(1U << static_cast<unsigned>(function));
}

/// Table 8-92: bits 0 … 7 are the firmware's; a write does not change them.
inline constexpr std::uint16_t kFirmwareOutputBits = 0x00FF;

/// Table 8-93: an EPOS2 24/5 has four digital outputs.
inline constexpr unsigned kDigitalOutputCount = 4;

/// 0x2079 sub 1 … 4 and 0x2078 sub 2, 3 with their defaults (tables 8-93, 8-92).
struct DigitalOutputConfiguration {
    std::array<std::uint16_t, kDigitalOutputCount> functions{15, 14, 13, 12};
    std::uint16_t mask = 0;
    std::uint16_t polarity = 0;

    /// Whether an output carries the holding brake (8.2.72).
    bool has(OutputFunction function) const;
};

/// The digital output pins of an EPOS2 24/5 (8.2.59, 8.2.60). Each pin carries the functionality
/// 0x2079 assigns it; it follows that functionality's state (0x2078 sub 1), inverted where the
/// polarity has its bit, and only while the mask has its bit ("only digital outputs will be
/// modified that have set its bit to 1"): otherwise it keeps its level. The reserved and unused
/// configurations (3 … 10) drive nothing; such a pin stays low. Pins start low (power-on).
class DigitalOutputs {
public:
    void configure(const DigitalOutputConfiguration& config) {
        config_ = config;
        applied_.reset();
    }
    const DigitalOutputConfiguration& configuration() const { return config_; }

    /// The functionality states (0x2078 sub 1) applied to the pins.
    void update(std::uint16_t states);
    /// The pins' levels, bit n-1 for output n.
    std::uint8_t levels() const { return levels_; }

private:
    DigitalOutputConfiguration config_;
    std::uint8_t levels_ = 0;
    /// The states last applied under config_: applying them again sets each driven pin to the
    /// level it has and leaves the others, so update() has nothing to do (it runs every period).
    std::optional<std::uint16_t> applied_;
};

} // namespace eposp::drives::epos2
