#pragma once

#include <array>
#include <cstdint>

namespace eposp::drives::epos2 {

/// EPOS2 FW spec table 8-90: which edges of the position marker functionality capture.
enum class MarkerEdge : std::uint8_t { Both = 0, Rising = 1, Falling = 2 };

/// Table 8-91: what the marker captures.
enum class MarkerMode : std::uint8_t {
    Continuous = 0,
    Single = 1,
    Multiple = 2,
    SingleAndStop = 3
};

/// The Position Marker 0x2074 (8.2.58): the actual position captured at the edges of the position
/// marker functionality (0x2071 bit 3, executed when 0x2071 sub 4 has bit 3). The counter counts
/// the captured edges: Single stops at 1, Multiple at 3 (captured position and both history
/// entries full), Continuous counts on (modulo 2^16) and the oldest position leaves the
/// history. Writing the counter 0 clears it and the positions, and captures again. Edges are
/// sampled every control period (1 ms), which is also the spec's input filter time.
class PositionMarker {
public:
    void configure(MarkerEdge edge, MarkerMode mode);

    /// One control period: the marker functionality's state and whether it is executed. True
    /// when this period captured in Single & Stop mode: the motion stops with a slow-down ramp.
    bool update(bool state, bool executed, std::int32_t position);
    /// A homing sequence starts: captured position, history and counter reset; no capture until
    /// it ends (8.2.58: "disables the Position Marker and resets the captured position").
    void homing_started();
    void set_homing(bool in_progress) { homing_ = in_progress; }
    /// 0x2074 sub 4 written: 0 clears counter and positions.
    void counter_written(std::uint16_t counter);

    std::int32_t captured() const { return positions_[0]; }
    std::int32_t history(unsigned n) const { return positions_.at(n); } ///< n = 1, 2
    std::uint16_t counter() const { return counter_; }

private:
    bool capturing() const;

    MarkerEdge edge_ = MarkerEdge::Both;
    MarkerMode mode_ = MarkerMode::Single;
    bool before_ = false;
    bool homing_ = false;
    std::uint16_t counter_ = 0;
    std::array<std::int32_t, 3> positions_{}; ///< captured, history [1], history [2]
};

} // namespace eposp::drives::epos2
