#include "plc_objects.hpp"

#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/vm/process_image.hpp"

#include <algorithm>

namespace eposp::device {
namespace {

canopen::AbortCode program_control(Plc& plc, std::uint16_t value, const ProgramStart& start) {
    vm::PlcRuntime& runtime = plc.runtime();
    if (value == static_cast<std::uint16_t>(ProgramControl::Stopped)) {
        if (runtime.state() == vm::ProgramState::Running) {
            runtime.stop();
        }
        return canopen::AbortCode::None;
    }
    // No program, one that runs, or one that cannot start.
    return start(static_cast<vm::StartMode>(value)) ? canopen::AbortCode::DeviceState
                                                    : canopen::AbortCode::None;
}

void bind_program_control(canopen::ObjectDictionary& od, Plc& plc, ProgramStart start) {
    canopen::SubObject& control = *od.find(kProgramControlIndex, 0);
    control.on_read = [&plc] {
        return canopen::encode(plc.runtime().program_control());
    };
    control.on_write =
        checked_write(std::move(control.on_write),
                      [&plc, start = std::move(start)](std::span<const std::uint8_t> value) {
                          return program_control(plc, canopen::decode<std::uint16_t>(value), start);
                      });
}

void bind_process_image(canopen::ObjectDictionary& od, Plc& plc) {
    // Inputs: what is written goes into the image the next task cycle reads.
    for (const vm::ProcessImageObject& object : vm::kInputObjects) {
        od.on_change(object.index, [&od, &plc](std::uint16_t index, std::uint8_t sub_index) {
            const auto entry = plc.runtime().process_image().entry(index, sub_index);
            if (entry) {
                const canopen::Bytes value = od.get(index, sub_index);
                std::copy_n(value.begin(), std::min(value.size(), entry->size()), entry->begin());
            }
        });
    }
    // Outputs: read from the image the last task cycle published.
    for (const vm::ProcessImageObject& object : vm::kOutputObjects) {
        for (std::uint8_t sub = 1; sub <= vm::kEntriesPerObject; ++sub) {
            od.find(object.index, sub)->on_read = [&plc, index = object.index, sub] {
                const auto entry = plc.runtime().process_image().entry(index, sub);
                return entry ? canopen::Bytes(entry->begin(), entry->end()) : canopen::Bytes{};
            };
        }
    }
}

} // namespace

canopen::SubObject::WriteHook checked_write(canopen::SubObject::WriteHook check,
                                            canopen::SubObject::WriteHook action) {
    return [check = std::move(check),
            action = std::move(action)](std::span<const std::uint8_t> value) {
        if (check) {
            if (const canopen::AbortCode refused = check(value);
                refused != canopen::AbortCode::None) {
                return refused;
            }
        }
        return action(value);
    };
}

canopen::AbortCode restore_permitted(const Plc& plc) {
    return plc.runtime().state() == vm::ProgramState::Running ? canopen::AbortCode::DeviceState
                                                              : canopen::AbortCode::None;
}

void bind_plc(canopen::ObjectDictionary& od, Plc& plc, ProgramStart start) {
    bind_program_control(od, plc, std::move(start));
    bind_process_image(od, plc);
    plc.on_error([&od](const RaisedError& error) {
        record_error(od, {.code = error.code, .port = 0, .node = 0, .warning = false});
    });
}

} // namespace eposp::device
