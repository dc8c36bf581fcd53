#pragma once

#include "eposp/device/network_file.hpp"
#include "eposp/yaml/reader.hpp"

#include <filesystem>

namespace eposp::device {

/// One entry of the network file's `escon2` list; `base` is the file's directory (for `plant`).
/// Its parameters are written into a dictionary of its hardware as they are read, so that one
/// the device refuses (a value out of range, a rule of the manual) is an error at its line.
NetworkEscon2 read_escon2(yaml::Reader& in, const YAML::Node& node,
                          const std::filesystem::path& base);

} // namespace eposp::device
