#pragma once

#include "eposp/core/result.hpp"

#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::device {

/// One axis of an axis trace (AxisTrace's CSV): its samples over time.
struct AxisSeries {
    std::uint8_t axis = 0;
    std::vector<double> time_s;
    std::vector<double> position;   ///< actual position, qc
    std::vector<double> velocity;   ///< actual velocity, rpm
    std::vector<double> current;    ///< current, mA
    std::vector<std::string> state; ///< PLCopen state; empty strings in older traces
};

/// The axes of an axis trace in the order they first appear; the error names the line that
/// is not a trace row (`name:line: …`).
core::Result<std::vector<AxisSeries>> read_axis_trace(std::istream& in, std::string_view name);

/// A self-contained SVG drawing: per axis, position, velocity and current over time, with the
/// PLCopen state as coloured bands under the position.
std::string plot_svg(const std::vector<AxisSeries>& axes);

} // namespace eposp::device
