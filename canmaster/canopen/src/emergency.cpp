#include "eposp/canopen/emergency.hpp"

namespace eposp::canopen {

void ErrorCondition::change(bool present, const EmergencyCallback& raise,
                            const ErrorResolvedCallback& resolve) {
    present_ = present;
    const auto& tell = present ? raise : resolve;
    if (tell) {
        tell(code_);
    }
}

} // namespace eposp::canopen
