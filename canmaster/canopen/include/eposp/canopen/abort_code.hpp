#pragma once

#include <cstdint>
#include <string_view>

namespace eposp::canopen {

/// SDO abort codes: CiA 301 7.2.4.3.17 (table 22) and the maxon-specific codes of the EPOS2
/// firmware specification 4.3 (table 4-12). `None` is "no error", the code a successful
/// access reports over the maxon serial protocol.
enum class AbortCode : std::uint32_t {
    None = 0x0000'0000,
    ToggleBit = 0x0503'0000,
    SdoTimeout = 0x0504'0000,
    CommandSpecifier = 0x0504'0001,
    InvalidBlockSize = 0x0504'0002,
    InvalidSequenceNumber = 0x0504'0003,
    CrcError = 0x0504'0004,
    OutOfMemory = 0x0504'0005,
    UnsupportedAccess = 0x0601'0000,
    WriteOnly = 0x0601'0001,
    ReadOnly = 0x0601'0002,
    ObjectDoesNotExist = 0x0602'0000,
    NotMappable = 0x0604'0041,
    PdoLengthExceeded = 0x0604'0042,
    ParameterIncompatibility = 0x0604'0043,
    InternalIncompatibility = 0x0604'0047,
    HardwareError = 0x0606'0000,
    LengthMismatch = 0x0607'0010,
    LengthTooHigh = 0x0607'0012,
    LengthTooLow = 0x0607'0013,
    SubIndexDoesNotExist = 0x0609'0011,
    InvalidValue = 0x0609'0030,
    ValueTooHigh = 0x0609'0031,
    ValueTooLow = 0x0609'0032,
    MaxLessThanMin = 0x0609'0036,
    ResourceNotAvailable = 0x060A'0023,
    GeneralError = 0x0800'0000,
    TransferOrStore = 0x0800'0020,
    LocalControl = 0x0800'0021,
    DeviceState = 0x0800'0022,
    NoDictionary = 0x0800'0023,
    NoDataAvailable = 0x0800'0024,
    // maxon (EPOS2 firmware specification, table 4-12)
    WrongNmtState = 0x0F00'FFC0,
    IllegalCommand = 0x0F00'FFBF,
    PasswordIncorrect = 0x0F00'FFBE,
    NotInServiceMode = 0x0F00'FFBC,
    WrongCanId = 0x0F00'FFB9,
};

/// The name the specification gives the code ("Toggle Error", "Object does not exist Error").
std::string_view describe(AbortCode code);

} // namespace eposp::canopen
