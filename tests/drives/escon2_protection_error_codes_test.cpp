// The codes the ESCON2's I/O and protection classes raise are rows of table 110 (ESCON2 FW spec
// 7.1), so the drive finds their error register bits and reaction there.
#include "eposp/drives/escon2/device_errors.hpp"
#include "eposp/drives/escon2/protection/device_error_code.hpp"

#include <gtest/gtest.h>

namespace eposp::drives::escon2 {
namespace {

TEST(Escon2ProtectionErrorCodes, EveryRaisedCodeIsARowOfTable110) {
    using enum DeviceErrorCode;
    for (const DeviceErrorCode code :
         {Overvoltage, Undervoltage, ThermalPowerStageOverload, ThermalPowerStageOverloadWarning,
          ThermalLogicSectionOverload, NegativeLimitSwitch, PositiveLimitSwitch,
          DigitalInput1PwmFrequencyWarning, DigitalInput1PwmDutyCycleWarning, DigitalInput1PwmError,
          DigitalInput2PwmFrequencyWarning, DigitalInput2PwmDutyCycleWarning,
          DigitalInput2PwmError, SystemOverloadedWarning, Watchdog, SystemPeakOverloaded}) {
        const auto value = static_cast<std::uint16_t>(code);
        EXPECT_EQ(device_error(value).code, value);
    }
    EXPECT_EQ(device_error(static_cast<std::uint16_t>(NegativeLimitSwitch)).reaction,
              FaultReactionCode::QuickStop);
    EXPECT_EQ(device_error(static_cast<std::uint16_t>(DigitalInput2PwmDutyCycleWarning)).reaction,
              FaultReactionCode::Warning);
}

} // namespace
} // namespace eposp::drives::escon2
