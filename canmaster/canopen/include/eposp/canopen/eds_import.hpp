#pragma once

#include "eposp/canopen/device_info.hpp"
#include "eposp/canopen/nmt_state.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/result.hpp"

#include <optional>
#include <string_view>

namespace eposp::canopen {

struct ImportedEds {
    ObjectDictionary dictionary; ///< values at their defaults (or a DCF's ParameterValue)
    DeviceInfo device;
};

/// Builds a dictionary from an EDS or DCF (CiA 306 v1.3): the objects the three object lists
/// name, with their sub-objects ([XXXXsubY] or CompactSubObj), types, access, defaults and
/// limits. Numbers may be decimal, 0x-hex or 0-octal; `$NODEID+0x180` takes `node_id` (an error
/// without it); keys and section names are compared without regard to case. A DCF's
/// ParameterValue becomes the current value. Persistence is not part of an EDS: no sub-object
/// comes back persistent. Any malformed input is an error naming `source_name` and the line.
core::Result<ImportedEds> import_eds(std::string_view text, std::string_view source_name,
                                     std::optional<NodeId> node_id = std::nullopt);

} // namespace eposp::canopen
