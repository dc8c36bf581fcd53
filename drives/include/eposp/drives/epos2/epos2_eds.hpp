#pragma once

#include <string>

namespace eposp::drives::epos2 {

/// The EDS (CiA 306) of the EPOS2 dictionary as it ships in drives/epos2/epos2.eds: the
/// dictionary of node-ID 1 with its defaults, exported by canmaster's export_eds().
std::string epos2_eds();

} // namespace eposp::drives::epos2
