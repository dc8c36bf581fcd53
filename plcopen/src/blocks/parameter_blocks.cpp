// The blocks that read and write an axis' parameters and actual values by SDO (PLCopen Motion
// Control Part 1, 3.14 - 3.20): the PLCopen parameter numbers mapped onto the EPOS2's objects,
// and any object of the drive by its index and sub-index.

#include "block_definition.hpp"
#include "execute_block.hpp"

#include <optional>

namespace eposp::plcopen::blocks {

namespace {

/// An object of the drive a parameter number names; `size` 0 when only the drive knows it.
struct DriveObject {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    std::uint8_t size = 4;
    bool is_signed = false;
    bool writable = true;
};

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

std::int32_t decode(const SdoReply& reply, bool is_signed) {
    if (is_signed && reply.size == 1) {
        return static_cast<std::int8_t>(reply.value);
    }
    if (is_signed && reply.size == 2) {
        return static_cast<std::int16_t>(reply.value);
    }
    return static_cast<std::int32_t>(reply.value);
}

/// An Enable block that keeps reading one object of its axis: Valid once a value came.
BlockDefinition reader(std::string_view name, std::vector<BlockVariable> inputs,
                       BlockVariable value,
                       std::function<std::optional<DriveObject>(vm::NativeBlock&)> object) {
    std::vector<BlockVariable> variables{axis_ref(), input("Enable", "BOOL")};
    variables.insert(variables.end(), inputs.begin(), inputs.end());
    const std::size_t first = variables.size();
    for (BlockVariable output_variable :
         {output("Valid", "BOOL"), output("Busy", "BOOL"), output("Error", "BOOL"),
          output("ErrorID", "WORD"), value, state("Request", "UDINT")}) {
        variables.push_back(output_variable);
    }
    const std::size_t valid = first, busy = first + 1, error = first + 2, error_id = first + 3,
                      result = first + 4, request = first + 5;
    const bool boolean = value.type == "BOOL";
    return {BlockInterface{name, std::move(variables)},
            [=](vm::NativeBlock& block, MotionLibrary& library) {
                const auto fail = [&](ErrorId id) {
                    set_flag(block, valid, false);
                    set_flag(block, error, true);
                    block.set<std::uint16_t>(error_id, static_cast<std::uint16_t>(id));
                };
                if (!flag(block, 1)) {
                    for (const std::size_t output_field : {valid, busy, error, error_id, result}) {
                        block.clear(output_field);
                    }
                    block.set<std::uint32_t>(request, 0);
                    return;
                }
                AxisDriver* axis = referenced_axis(block, library);
                const auto drive_object = object(block);
                if (axis == nullptr || axis->presence() == AxisPresence::Unassigned) {
                    fail(ErrorId::UnknownAxis);
                    return;
                }
                if (!drive_object) {
                    fail(ErrorId::InvalidParameter);
                    return;
                }
                set_flag(block, busy, true);
                SdoRequests& requests = library.requests();
                std::uint32_t pending = block.get<std::uint32_t>(request);
                if (pending != 0) {
                    if (const auto reply = requests.take(pending)) {
                        pending = 0;
                        if (reply->abort_code != 0) {
                            fail(ErrorId::SdoAbort);
                        } else {
                            const std::int32_t read = decode(*reply, drive_object->is_signed);
                            if (boolean) {
                                set_flag(block, result, read != 0);
                            } else {
                                block.set<std::int32_t>(result, read);
                            }
                            set_flag(block, valid, true);
                            set_flag(block, error, false);
                            block.set<std::uint16_t>(error_id, 0);
                        }
                    } else if (!requests.pending(pending)) {
                        pending = 0; // forgotten: ask again
                    }
                }
                if (pending == 0) {
                    pending =
                        requests.read(axis->number(), drive_object->index, drive_object->sub_index);
                }
                block.set<std::uint32_t>(request, pending);
            }};
}

BlockDefinition read_parameter(std::string_view name, std::string_view type) {
    return reader(
        name, {input("ParameterNumber", "DINT")}, output("Value", type),
        [](vm::NativeBlock& block) { return parameter_object(block.get<std::int32_t>(2)); });
}

BlockDefinition read_object(std::string_view name, std::string_view value, DriveObject object) {
    return reader(name, {}, output(value, "DINT"),
                  [object](vm::NativeBlock&) { return std::optional(object); });
}

/// MC_WriteParameter / MC_WriteBoolParameter: an object of unknown size is read first, so the
/// write has the size the drive expects.
BlockDefinition write_parameter(std::string_view name, std::string_view type) {
    std::vector<BlockVariable> variables{axis_ref(), input("Execute", "BOOL"),
                                         input("ParameterNumber", "DINT"), input("Value", type)};
    const auto outputs = execute_outputs("Done", false);
    variables.insert(variables.end(), outputs.begin(), outputs.end());
    variables.push_back(state("Writing", "BOOL"));
    variables.push_back(state("Target", "USINT"));
    BlockInterface declared{name, std::move(variables)};
    const ExecuteOutputs out(declared);
    const std::size_t writing = field(declared, "Writing");
    const std::size_t target = field(declared, "Target");
    const bool boolean = type == "BOOL";
    return {std::move(declared), [=](vm::NativeBlock& block, MotionLibrary& library) {
                SdoRequests& requests = library.requests();
                const auto drive_object = parameter_object(block.get<std::int32_t>(2));
                const std::uint32_t value =
                    boolean ? std::uint32_t{flag(block, 3)}
                            : static_cast<std::uint32_t>(block.get<std::int32_t>(3));
                if (out.begin(block)) {
                    AxisDriver* axis = referenced_axis(block, library);
                    if (axis == nullptr || axis->presence() == AxisPresence::Unassigned) {
                        out.failed(block, ErrorId::UnknownAxis);
                        return;
                    }
                    if (!drive_object || !drive_object->writable) {
                        out.failed(block, ErrorId::InvalidParameter);
                        return;
                    }
                    const bool size_known = drive_object->size != 0;
                    block.set<std::uint32_t>(
                        out.work, size_known ? requests.write(axis->number(), drive_object->index,
                                                              drive_object->sub_index, value,
                                                              drive_object->size)
                                             : requests.read(axis->number(), drive_object->index,
                                                             drive_object->sub_index));
                    set_flag(block, writing, size_known);
                    block.set<std::uint8_t>(target, axis->number());
                    set_flag(block, out.busy, true);
                }
                if (!flag(block, out.busy)) {
                    return;
                }
                const std::uint32_t request = block.get<std::uint32_t>(out.work);
                const auto reply = requests.take(request);
                if (!reply) {
                    if (!requests.pending(request)) {
                        out.failed(block, ErrorId::SdoAbort);
                    }
                    return;
                }
                if (reply->abort_code != 0) {
                    out.failed(block, ErrorId::SdoAbort);
                } else if (!flag(block, writing)) { // the read told the object's size
                    block.set<std::uint32_t>(
                        out.work, requests.write(block.get<std::uint8_t>(target),
                                                 drive_object->index, drive_object->sub_index,
                                                 value, reply->size != 0 ? reply->size : 4));
                    set_flag(block, writing, true);
                } else {
                    out.done(block);
                }
            }};
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
