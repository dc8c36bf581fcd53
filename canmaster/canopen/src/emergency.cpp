#include "eposp/canopen/emergency.hpp"

namespace eposp::canopen {

void ErrorCondition::set(bool present, const EmergencyCallback& raise,
                         const ErrorResolvedCallback& resolve) {
    if (present == present_) {
        return;
    }
    present_ = present;
    const auto& tell = present ? raise : resolve;
    if (tell) {
        tell(code_);
    }
}

} // namespace eposp::canopen
