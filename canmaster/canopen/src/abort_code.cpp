#include "eposp/canopen/abort_code.hpp"

namespace eposp::canopen {

// The names of the EPOS2 firmware specification 4.3 (table 4-12); the codes that table leaves
// out (block transfer, resources, dictionary) carry CiA 301 7.2.4.3.17's wording.
std::string_view describe(AbortCode code) {
    switch (code) {
    case AbortCode::None:
        return "No Communication Error";
    case AbortCode::ToggleBit:
        return "Toggle Error";
    case AbortCode::SdoTimeout:
        return "SDO Time Out";
    case AbortCode::CommandSpecifier:
        return "Client / Server Specifier Error";
    case AbortCode::InvalidBlockSize:
        return "Invalid block size";
    case AbortCode::InvalidSequenceNumber:
        return "Invalid sequence number";
    case AbortCode::CrcError:
        return "CRC error";
    case AbortCode::OutOfMemory:
        return "Out of Memory Error";
    case AbortCode::UnsupportedAccess:
        return "Access Error";
    case AbortCode::WriteOnly:
        return "Write Only";
    case AbortCode::ReadOnly:
        return "Read Only";
    case AbortCode::ObjectDoesNotExist:
        return "Object does not exist Error";
    case AbortCode::NotMappable:
        return "PDO mapping Error";
    case AbortCode::PdoLengthExceeded:
        return "PDO Length Error";
    case AbortCode::ParameterIncompatibility:
        return "General Parameter Error";
    case AbortCode::InternalIncompatibility:
        return "General internal Incompatibility Error";
    case AbortCode::HardwareError:
        return "Hardware Error";
    case AbortCode::LengthMismatch:
        return "Service Parameter Error";
    case AbortCode::LengthTooHigh:
        return "Service Parameter too long Error";
    case AbortCode::LengthTooLow:
        return "Service Parameter too short Error";
    case AbortCode::SubIndexDoesNotExist:
        return "Object Subindex Error";
    case AbortCode::InvalidValue:
        return "Value Range Error";
    case AbortCode::ValueTooHigh:
        return "Value too high Error";
    case AbortCode::ValueTooLow:
        return "Value too low Error";
    case AbortCode::MaxLessThanMin:
        return "Maximum less Minimum Error";
    case AbortCode::ResourceNotAvailable:
        return "Resource not available: SDO connection";
    case AbortCode::GeneralError:
        return "General Error";
    case AbortCode::TransferOrStore:
        return "Transfer or store Error";
    case AbortCode::LocalControl:
        return "Local Control Error";
    case AbortCode::DeviceState:
        return "Wrong Device State";
    case AbortCode::NoDictionary:
        return "No object dictionary present";
    case AbortCode::NoDataAvailable:
        return "No data available";
    case AbortCode::WrongNmtState:
        return "Wrong NMT State Error";
    case AbortCode::IllegalCommand:
        return "Illegal Command Error";
    case AbortCode::PasswordIncorrect:
        return "Password Error";
    case AbortCode::NotInServiceMode:
        return "Error Service Mode";
    case AbortCode::WrongCanId:
        return "Error CAN ID";
    }
    // A code received from the wire that neither table defines.
    return "Unknown abort code";
}

} // namespace eposp::canopen
