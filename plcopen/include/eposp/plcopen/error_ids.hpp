#pragma once

#include <cstdint>

namespace eposp::plcopen {

/// The ErrorID (WORD) of the motion blocks (docs/function-blocks.md, "Errors").
enum class ErrorId : std::uint16_t {
    None = 0x0000,
    UnknownAxis = 0x1001,       ///< AxisNo above 31, or no slave assigned to the axis
    CommunicationLost = 0x1003, ///< the axis' slave is not operational or stopped answering
    DriveFault = 0x1004,        ///< the drive is in its Fault state (MC_ReadAxisError tells why)
    InvalidInput = 0x1010,      ///< an input out of its range (a negative velocity …)
    InvalidParameter = 0x1011,  ///< a parameter number the axis does not have
    NotAllowed = 0x1020,        ///< the command is not allowed in the axis' PLCopen state
    AxisInErrorStop = 0x1021,   ///< the axis is in ErrorStop: only MC_Reset is accepted
    SdoAbort = 0x1030,          ///< the drive refused an SDO transfer (or it timed out)
    ModeNotConfirmed = 0x1040,  ///< 0x6061 did not confirm the mode of operation written
    HomingError = 0x1050,       ///< the drive reported a homing error (statusword bit 13)
    ResetFailed = 0x1060,       ///< the drive's fault did not clear
};

} // namespace eposp::plcopen
