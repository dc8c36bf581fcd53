#pragma once

#include "eposp/device/network_file.hpp"
#include "eposp/yaml/reader.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace eposp::device {

/// An ESCON2's machine from the mapping `node` (`section` in messages): its keys `hardware`,
/// `plant` (relative to `base`) and `parameters`, and the `more` keys the caller reads. The
/// parameters are written into a dictionary of its hardware as they are read, so that one the
/// device refuses (a value out of range, a rule of the manual) is an error at its line.
Escon2Machine
read_escon2_machine(yaml::Reader& in, const YAML::Node& node, std::string_view section,
                    const std::filesystem::path& base,
                    std::map<std::string, std::function<void(const YAML::Node&)>> more = {});

/// One entry of the network file's `escon2` list; `base` is the file's directory (for `plant`).
/// Its parameters are written into a dictionary of its hardware as they are read, so that one
/// the device refuses (a value out of range, a rule of the manual) is an error at its line.
NetworkEscon2 read_escon2(yaml::Reader& in, const YAML::Node& node,
                          const std::filesystem::path& base);

} // namespace eposp::device
