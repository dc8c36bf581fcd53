#pragma once

#include "eposp/canopen/device_info.hpp"
#include "eposp/canopen/object_dictionary.hpp"

#include <string>

namespace eposp::canopen {

/// The electronic data sheet of a dictionary (CiA 306 v1.3): [FileInfo], [DeviceInfo],
/// [DummyUsage], [Comments], the [MandatoryObjects] / [OptionalObjects] / [ManufacturerObjects]
/// lists and one [XXXX] / [XXXXsubY] section per object with its default values. The same
/// dictionary and info always give the same text, and import_eds() reads it back to them.
std::string export_eds(const ObjectDictionary& dictionary, const DeviceInfo& info);

} // namespace eposp::canopen
