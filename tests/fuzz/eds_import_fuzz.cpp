// EDS/DCF import (CiA 306) of arbitrary text: an error or a dictionary, never a crash. What
// imports must export to an EDS that imports back to the same export (eds_export.hpp).

#include "eposp/canmaster/canopen/eds_export.hpp"
#include "eposp/canmaster/canopen/eds_import.hpp"
#include "fuzz_check.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

constexpr eposp::canopen::NodeId kNodeId = 5; // what `$NODEID` expressions take

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace eposp::canopen;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto imported = import_eds(text, "fuzz.eds", kNodeId);
    if (!imported) {
        return 0;
    }
    const std::string exported = export_eds(imported->dictionary, imported->device);
    const auto reimported = import_eds(exported, "exported.eds", kNodeId);
    eposp::fuzz::require(reimported.ok(), "an exported EDS imports");
    eposp::fuzz::require(export_eds(reimported->dictionary, reimported->device) == exported,
                         "an exported EDS imports back to the same export");
    return 0;
}
