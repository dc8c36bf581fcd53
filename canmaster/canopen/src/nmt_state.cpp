#include "eposp/canopen/nmt_state.hpp"

namespace eposp::canopen {

// CiA 301 7.3.2.2 names the states.
std::string_view to_string(NmtState state) {
    switch (state) {
    case NmtState::Initialising:
        return "Initialising";
    case NmtState::Stopped:
        return "Stopped";
    case NmtState::Operational:
        return "Operational";
    case NmtState::PreOperational:
        return "Pre-operational";
    }
    // A state byte received from the wire that CiA 301 does not define.
    return "unknown";
}

} // namespace eposp::canopen
