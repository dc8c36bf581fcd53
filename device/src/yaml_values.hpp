#pragma once

// Values of the network file that more than one of its sections reads.

#include "eposp/core/time.hpp"
#include "eposp/drives/plant/axis_file.hpp"
#include "eposp/yaml/reader.hpp"

#include <cstdint>
#include <filesystem>
#include <fmt/format.h>
#include <string_view>

namespace eposp::device {

inline core::Duration duration(yaml::Reader& in, const YAML::Node& node, std::string_view what) {
    const auto text = in.scalar<std::string>(node, what);
    const auto parsed = core::parse_duration(text);
    if (!parsed) {
        in.fail(node, fmt::format("{} must be a duration such as 500ms or 1s", what));
    }
    return *parsed;
}

template <typename T>
T in_range(yaml::Reader& in, const YAML::Node& node, std::string_view what, std::int64_t low,
           std::int64_t high) {
    const auto value = in.scalar<std::int64_t>(node, what);
    if (value < low || value > high) {
        in.fail(node, fmt::format("{} must be {}..{}", what, low, high));
    }
    return static_cast<T>(value);
}

/// A simulated drive's machine: the axis file `node` names relative to `base`.
inline drives::plant::AxisParameters read_plant(yaml::Reader& in, const YAML::Node& node,
                                                const std::filesystem::path& base) {
    const auto path = base / in.scalar<std::string>(node, "plant");
    auto axis = drives::plant::load_axis_file(path);
    if (!axis) {
        in.fail(node, fmt::format("plant {}: {}", path.string(), axis.error()));
    }
    return std::move(*axis);
}

} // namespace eposp::device
