#pragma once

#include "eposp/canopen/device_info.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"

#include <cstdint>
#include <string>

namespace eposp::canopen {

/// The electronic data sheet of a dictionary (CiA 306 v1.3): [FileInfo], [DeviceInfo],
/// [DummyUsage], [Comments], the [MandatoryObjects] / [OptionalObjects] / [ManufacturerObjects]
/// lists and one [XXXX] / [XXXXsubY] section per object with its default values. The same
/// dictionary and info always give the same text, and import_eds() reads it back to them.
std::string export_eds(const ObjectDictionary& dictionary, const DeviceInfo& info);

/// [DeviceComissioning] of a DCF (CiA 306 4.5.4, the standard's spelling): where the node sits
/// in its network.
struct DeviceCommissioning {
    NodeId node_id = 0;
    std::string node_name;
    std::uint32_t baudrate_kbit = 0;
    std::uint32_t net_number = 1;
    std::string network_name;
    bool canopen_manager = false; ///< the node is the network's CANopen manager
};

/// The device configuration file (CiA 306 DCF) of a configured dictionary: its EDS with
/// [DeviceComissioning] after [DeviceInfo] and, on each read-write value that differs from its
/// default, the configured value as ParameterValue. import_eds() reads those values back.
std::string export_dcf(const ObjectDictionary& dictionary, const DeviceInfo& info,
                       const DeviceCommissioning& commissioning);

} // namespace eposp::canopen
