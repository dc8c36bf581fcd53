// maxon's utility blocks (MU_*) for what programs need beyond PLCopen: the drive's digital and
// analog I/O, single bits of any object, and the error history of a drive or of the EPOS P. The
// EPOS2 objects are those of its firmware specification 8.2.57 - 8.2.63 and 8.2.3.

#include "sdo_blocks.hpp"

namespace eposp::plcopen::blocks {

namespace {

constexpr std::uint16_t kDigitalInputStates = 0x2071;  // sub 1: the functionalities' states
constexpr std::uint16_t kDigitalOutputStates = 0x2078; // sub 1
constexpr std::uint16_t kAnalogInputs = 0x207C;        // sub 1, 2: mV
constexpr std::uint16_t kErrorHistory = 0x1003;

/// A bit number input (0..15 of a 16-bit object, 0..31 of any object for the bit blocks).
std::optional<DriveObject> bit_object(vm::NativeBlock& block, std::size_t bit_field,
                                      DriveObject object, std::uint8_t bits) {
    return block.get<std::uint8_t>(bit_field) < bits ? std::optional(object) : std::nullopt;
}

std::int32_t bit_of(std::int32_t value, std::uint8_t bit) {
    return (static_cast<std::uint32_t>(value) >> bit) & 1U;
}

std::uint32_t with_bit(std::uint32_t value, std::uint8_t bit, bool state) {
    return state ? value | (1U << bit) : value & ~(1U << bit);
}

// Inputs are fields 2, 3, … after Axis and Enable/Execute.
BlockDefinition get_digital_input() {
    return reader(
        {.name = "MU_GetDigitalInput",
         .inputs = {input("Input", "USINT")},
         .value = output("State", "BOOL"),
         .object =
             [](vm::NativeBlock& block) {
                 return bit_object(
                     block, 2,
                     {.index = kDigitalInputStates, .sub_index = 1, .size = 2, .writable = false},
                     16);
             },
         .invalid = ErrorId::InvalidInput,
         .convert =
             [](vm::NativeBlock& block, std::int32_t read) {
                 return bit_of(read, block.get<std::uint8_t>(2));
             }});
}

BlockDefinition set_digital_output() {
    return writer({.name = "MU_SetDigitalOutput",
                   .inputs = {input("Output", "USINT"), input("State", "BOOL")},
                   .object =
                       [](vm::NativeBlock& block) {
                           return bit_object(
                               block, 2, {.index = kDigitalOutputStates, .sub_index = 1, .size = 2},
                               16);
                       },
                   .invalid = ErrorId::InvalidInput,
                   .read_first = true,
                   .value =
                       [](vm::NativeBlock& block, const SdoReply* read) {
                           return with_bit(read != nullptr ? read->value : 0,
                                           block.get<std::uint8_t>(2), flag(block, 3));
                       }});
}

BlockDefinition get_analog_input() {
    return reader({.name = "MU_GetAnalogInput",
                   .inputs = {input("Input", "USINT")},
                   .value = output("Value", "DINT"),
                   .object = [](vm::NativeBlock& block) -> std::optional<DriveObject> {
                       const auto number = block.get<std::uint8_t>(2);
                       if (number < 1 || number > 2) {
                           return std::nullopt;
                       }
                       return DriveObject{.index = kAnalogInputs,
                                          .sub_index = number,
                                          .size = 2,
                                          .is_signed = true,
                                          .writable = false};
                   },
                   .invalid = ErrorId::InvalidInput});
}

/// Index : UINT, SubIndex : USINT, BitNumber : USINT (0..31).
std::optional<DriveObject> object_bit(vm::NativeBlock& block) {
    return bit_object(
        block, 4,
        {.index = block.get<std::uint16_t>(2), .sub_index = block.get<std::uint8_t>(3), .size = 0},
        32);
}

BlockDefinition get_bit_state() {
    return reader({.name = "MU_GetBitState",
                   .inputs = {input("Index", "UINT"), input("SubIndex", "USINT"),
                              input("BitNumber", "USINT")},
                   .value = output("State", "BOOL"),
                   .object = object_bit,
                   .invalid = ErrorId::InvalidInput,
                   .convert = [](vm::NativeBlock& block, std::int32_t read) {
                       return bit_of(read, block.get<std::uint8_t>(4));
                   }});
}

BlockDefinition set_bit_state() {
    return writer({.name = "MU_SetBitState",
                   .inputs = {input("Index", "UINT"), input("SubIndex", "USINT"),
                              input("BitNumber", "USINT"), input("State", "BOOL")},
                   .object = object_bit,
                   .invalid = ErrorId::InvalidInput,
                   .read_first = true,
                   .value = [](vm::NativeBlock& block, const SdoReply* read) {
                       return with_bit(read != nullptr ? read->value : 0,
                                       block.get<std::uint8_t>(4), flag(block, 5));
                   }});
}

// The error history of the axis' drive, or of the EPOS P itself for AxisNo 255.
BlockDefinition get_device_error_count() {
    return reader({.name = "MU_GetDeviceErrorCount",
                   .value = output("ErrorCount", "USINT"),
                   .object =
                       [](vm::NativeBlock&) {
                           return std::optional(
                               DriveObject{.index = kErrorHistory, .size = 1, .writable = false});
                       },
                   .controller_too = true});
}

BlockDefinition get_device_error() {
    return reader({.name = "MU_GetDeviceError",
                   .inputs = {input("ErrorNumber", "USINT")},
                   .value = output("DeviceErrorCode", "UDINT"),
                   .object = [](vm::NativeBlock& block) -> std::optional<DriveObject> {
                       const auto number = block.get<std::uint8_t>(2);
                       if (number < 1 || number > 254) {
                           return std::nullopt;
                       }
                       return DriveObject{
                           .index = kErrorHistory, .sub_index = number, .writable = false};
                   },
                   .invalid = ErrorId::InvalidInput,
                   .controller_too = true});
}

} // namespace

std::vector<BlockDefinition> maxon_blocks() {
    return {get_digital_input(), set_digital_output(),     get_analog_input(), get_bit_state(),
            set_bit_state(),     get_device_error_count(), get_device_error()};
}

} // namespace eposp::plcopen::blocks
