// The blocks that read and write an axis' parameters and actual values by SDO (PLCopen Motion
// Control Part 1, 3.14 - 3.20): the PLCopen parameter numbers mapped onto the EPOS2's objects,
// and any object of the drive by its index and sub-index.

#include "sdo_blocks.hpp"

#include <optional>

namespace eposp::plcopen::blocks {

namespace {

/// PLCopen's parameter numbers 1..16 (Part 1, table 3.14) as the EPOS2 has them, and from
/// 16#100000 on any object: 16#iiiiss is index 16#iiii, sub-index 16#ss.
std::optional<DriveObject> parameter_object(std::int32_t number) {
    switch (number) {
    case 1: // CommandedPosition
        return DriveObject{.index = 0x6062, .is_signed = true, .writable = false};
    case 2: // SWLimitPos
        return DriveObject{.index = 0x607D, .sub_index = 2, .is_signed = true};
    case 3: // SWLimitNeg
        return DriveObject{.index = 0x607D, .sub_index = 1, .is_signed = true};
    case 7: // MaxPositionLag: the following error window
        return DriveObject{.index = 0x6065};
    case 8: // MaxVelocitySystem: the motor's maximal speed
        return DriveObject{.index = 0x6410, .sub_index = 4};
    case 9: // MaxVelocityAppl: the maximal profile velocity
        return DriveObject{.index = 0x607F};
    case 10: // ActualVelocity
        return DriveObject{.index = 0x606C, .is_signed = true, .writable = false};
    case 11: // CommandedVelocity
        return DriveObject{.index = 0x606B, .is_signed = true, .writable = false};
    case 12: // MaxAccelerationSystem; the EPOS2 has one limit for all four
    case 13:
    case 14:
    case 15:
        return DriveObject{.index = 0x60C5};
    default:
        break;
    }
    if (number >= 0x100000) {
        return DriveObject{.index = static_cast<std::uint16_t>(number >> 8),
                           .sub_index = static_cast<std::uint8_t>(number),
                           .size = 0};
    }
    return std::nullopt; // 4, 5, 6 (limit enables, lag monitoring), 16 (jerk): no such object
}

BlockDefinition read_parameter(std::string_view name, std::string_view type) {
    return reader({.name = name,
                   .inputs = {input("ParameterNumber", "DINT")},
                   .value = output("Value", type),
                   .object = [](vm::NativeBlock& block) {
                       return parameter_object(block.get<std::int32_t>(2));
                   }});
}

BlockDefinition read_object(std::string_view name, std::string_view value, DriveObject object) {
    return reader(
        {.name = name, .value = output(value, "DINT"), .object = [object](vm::NativeBlock&) {
             return std::optional(object);
         }});
}

/// An object given by number is read first, so the write has the size the drive expects.
BlockDefinition write_parameter(std::string_view name, std::string_view type) {
    const bool boolean = type == "BOOL";
    return writer(
        {.name = name,
         .inputs = {input("ParameterNumber", "DINT"), input("Value", type)},
         .object =
             [](vm::NativeBlock& block) { return parameter_object(block.get<std::int32_t>(2)); },
         .value =
             [boolean](vm::NativeBlock& block, const SdoReply*) {
                 return boolean ? std::uint32_t{flag(block, 3)}
                                : static_cast<std::uint32_t>(block.get<std::int32_t>(3));
             }});
}

} // namespace

std::vector<BlockDefinition> parameter_blocks() {
    return {read_parameter("MC_ReadParameter", "DINT"),
            read_parameter("MC_ReadBoolParameter", "BOOL"),
            write_parameter("MC_WriteParameter", "DINT"),
            write_parameter("MC_WriteBoolParameter", "BOOL"),
            read_object("MC_ReadActualVelocity", "Velocity",
                        {.index = 0x606C, .is_signed = true, .writable = false}),
            read_object("MC_ReadActualCurrent", "Current",
                        {.index = 0x6078, .size = 2, .is_signed = true, .writable = false}),
            // The EPOS2 has no torque constant: the torque is given as its motor current, mA.
            read_object("MC_ReadActualTorque", "Torque",
                        {.index = 0x6078, .size = 2, .is_signed = true, .writable = false})};
}

} // namespace eposp::plcopen::blocks
