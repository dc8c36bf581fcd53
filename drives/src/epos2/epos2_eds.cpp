#include "eposp/drives/epos2/epos2_eds.hpp"

#include "eposp/canopen/eds_export.hpp"
#include "eposp/drives/epos2/epos2_dictionary.hpp"

#include <utility>

namespace eposp::drives::epos2 {

std::string epos2_eds() {
    // The store is never written: an export only reads the defaults.
    Epos2DictionaryConfig config;
    config.node_id = 1;
    config.parameter_file = "epos2-parameters.bin";
    const Epos2Dictionary dictionary(std::move(config));
    return canopen::export_eds(dictionary.objects(), epos2_device_info());
}

} // namespace eposp::drives::epos2
