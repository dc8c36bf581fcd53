#include "eposp/drives/plant/pid_controller.hpp"

namespace eposp::drives::plant {

void PidController::reset() {
    integral_ = 0;
    previous_error_ = 0;
    has_previous_ = false;
}

} // namespace eposp::drives::plant
