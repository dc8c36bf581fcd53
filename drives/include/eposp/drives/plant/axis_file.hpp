#pragma once

#include "eposp/core/result.hpp"
#include "eposp/drives/plant/servo_axis.hpp"

#include <filesystem>
#include <string_view>

namespace eposp::drives::plant {

/// A simulated machine from YAML (format and example in docs/epos2.md): motor, gearhead,
/// encoder, load, power stage, controller gains and switch positions, each section optional and
/// starting from reference_axis(). Units are those of maxon's data sheets and of the EPOS2
/// dictionary. Unknown or duplicate keys, a second document, values of the wrong kind or outside
/// their allowed values (a dictionary default: its entry's value range; a physical value: finite
/// and plausible), limit switches the wrong way round and parameters validate() refuses are
/// errors naming the file, line and column. `source` names the text in messages.
core::Result<AxisParameters> parse_axis_file(std::string_view text, std::string_view source);
core::Result<AxisParameters> load_axis_file(const std::filesystem::path& path);

} // namespace eposp::drives::plant
