// EDS/DCF import (CiA 306) of arbitrary text, with and without a node-ID: an error or a
// dictionary, never a crash. What imports must export to an EDS that imports back to the same
// export (eds_export.hpp).

#include "eposp/canopen/eds_export.hpp"
#include "eposp/canopen/eds_import.hpp"
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
    // Without a node-ID only `$NODEID` can fail that passed with one.
    const auto without_node_id = import_eds(text, "fuzz.eds");
    eposp::fuzz::require(!without_node_id || imported,
                         "a file that imports without a node-ID imports with one");
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
