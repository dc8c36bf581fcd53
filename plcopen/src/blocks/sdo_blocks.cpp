#include "sdo_blocks.hpp"

#include "execute_block.hpp"

#include <variant>

namespace eposp::plcopen::blocks {

namespace {

using Target = std::variant<AxisNumber, NodeAddress>;

/// Where the block's AXIS_REF points: an assigned axis, or the EPOS P itself if allowed.
std::optional<Target> target_of(vm::NativeBlock& block, MotionLibrary& library,
                                bool controller_too) {
    const auto axis_ref = block.referenced(kAxisField, 1);
    if (controller_too && !axis_ref.empty() && axis_ref[0] == kControllerAxis) {
        return Target{NodeAddress{}};
    }
    AxisDriver* axis = referenced_axis(block, library);
    if (axis == nullptr) {
        return std::nullopt;
    }
    return Target{axis->number()};
}

std::uint32_t start_read(SdoRequests& requests, const Target& target, const DriveObject& object) {
    return std::visit(
        [&](auto where) { return requests.read(where, object.index, object.sub_index); }, target);
}

std::uint32_t start_write(SdoRequests& requests, const Target& target, const DriveObject& object,
                          std::uint32_t value, std::uint8_t size) {
    return std::visit(
        [&](auto where) {
            return requests.write(where, object.index, object.sub_index, value, size);
        },
        target);
}

} // namespace

std::int32_t decode(const SdoReply& reply, bool is_signed) {
    if (is_signed && reply.size == 1) {
        return static_cast<std::int8_t>(reply.value);
    }
    if (is_signed && reply.size == 2) {
        return static_cast<std::int16_t>(reply.value);
    }
    return static_cast<std::int32_t>(reply.value);
}

BlockDefinition reader(ReaderSpec spec) {
    std::vector<BlockVariable> variables{axis_ref(), input("Enable", "BOOL")};
    variables.insert(variables.end(), spec.inputs.begin(), spec.inputs.end());
    const std::size_t valid = variables.size();
    for (const BlockVariable& variable :
         {output("Valid", "BOOL"), output("Busy", "BOOL"), output("Error", "BOOL"),
          output("ErrorID", "WORD"), spec.value, state("Request", "UDINT")}) {
        variables.push_back(variable);
    }
    const std::size_t busy = valid + 1, error = valid + 2, error_id = valid + 3, result = valid + 4,
                      request = valid + 5;
    const bool boolean = spec.value.type == "BOOL";
    const std::size_t value_size = vm::scalar_size(spec.value.scalar);
    BlockInterface declared{spec.name, std::move(variables)};
    return {std::move(declared), [=](vm::NativeBlock& block, MotionLibrary& library) {
                const auto fail = [&](ErrorId id) {
                    set_flag(block, valid, false);
                    set_flag(block, busy, false);
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
                const auto target = target_of(block, library, spec.controller_too);
                if (!target) {
                    fail(ErrorId::UnknownAxis);
                    return;
                }
                const auto object = spec.object(block);
                if (!object) {
                    fail(spec.invalid);
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
                            std::int32_t read = decode(*reply, object->is_signed);
                            if (spec.convert) {
                                read = spec.convert(block, read);
                            }
                            if (boolean) {
                                set_flag(block, result, read != 0);
                            } else if (value_size == 1) {
                                block.set<std::uint8_t>(result, static_cast<std::uint8_t>(read));
                            } else if (value_size == 2) {
                                block.set<std::uint16_t>(result, static_cast<std::uint16_t>(read));
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
                    pending = start_read(requests, *target, *object);
                }
                block.set<std::uint32_t>(request, pending);
            }};
}

BlockDefinition writer(WriterSpec spec) {
    std::vector<BlockVariable> variables{axis_ref(), input("Execute", "BOOL")};
    variables.insert(variables.end(), spec.inputs.begin(), spec.inputs.end());
    const auto outputs = execute_outputs("Done", false);
    variables.insert(variables.end(), outputs.begin(), outputs.end());
    variables.push_back(state("Writing", "BOOL"));
    variables.push_back(state("Target", "USINT"));
    BlockInterface declared{spec.name, std::move(variables)};
    const ExecuteOutputs out(declared);
    const std::size_t writing = field(declared, "Writing");
    const std::size_t target_field = field(declared, "Target");
    return {std::move(declared), [=](vm::NativeBlock& block, MotionLibrary& library) {
                SdoRequests& requests = library.requests();
                const auto object = spec.object(block);
                if (out.begin(block)) {
                    const auto target = target_of(block, library, false);
                    if (!target) {
                        out.failed(block, ErrorId::UnknownAxis);
                        return;
                    }
                    if (!object || !object->writable) {
                        out.failed(block, spec.invalid);
                        return;
                    }
                    const bool write_now = object->size != 0 && !spec.read_first;
                    block.set<std::uint32_t>(
                        out.work, write_now ? start_write(requests, *target, *object,
                                                          spec.value(block, nullptr), object->size)
                                            : start_read(requests, *target, *object));
                    set_flag(block, writing, write_now);
                    block.set<std::uint8_t>(target_field, std::get<AxisNumber>(*target));
                    set_flag(block, out.busy, true);
                }
                const auto reply = followed_reply(block, out, requests);
                if (!reply) {
                    return;
                }
                if (reply->abort_code != 0 || !object) {
                    out.failed(block, ErrorId::SdoAbort);
                } else if (!flag(block, writing)) { // the read gave the size and the old value
                    const std::uint8_t size = reply->size != 0 ? reply->size : object->size;
                    block.set<std::uint32_t>(
                        out.work, requests.write(block.get<std::uint8_t>(target_field),
                                                 object->index, object->sub_index,
                                                 spec.value(block, &*reply), size != 0 ? size : 4));
                    set_flag(block, writing, true);
                } else {
                    out.done(block);
                }
            }};
}

} // namespace eposp::plcopen::blocks
