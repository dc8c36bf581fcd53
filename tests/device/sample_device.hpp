#pragma once

#include <cstddef>
#include <string>

namespace eposp::device {

/// The node-ID the sample device is exported for (its COB-IDs in the EDS).
inline constexpr unsigned kSampleNodeId = 5;

/// The EDS that examples/canopen-node/sample-device.eds ships: an 8-bit digital I/O module
/// (CiA 401 style) with a value of every basic type, strings and a DOMAIN, exported by
/// export_eds() from the dictionary of a canopen::Node built on it.
std::string sample_device_eds();

/// How many entries (object sub-indices) that dictionary has, and how many of them read.
struct SampleDeviceEntries {
    std::size_t all = 0;
    std::size_t readable = 0;
};
SampleDeviceEntries sample_device_entries();

} // namespace eposp::device
