#include "program_download.hpp"

#include "eposp/canopen/value_codec.hpp"
#include "eposp/device/epos_p_dictionary.hpp"

namespace eposp::device {
namespace {

using canopen::AbortCode;

// A program loaded into the PLC without a download (plc().load()) counts too.
ProgramStatus program_status(const Plc& plc) {
    switch (plc.runtime().state()) {
    case vm::ProgramState::NotLoaded:
        return ProgramStatus::NoProgram;
    case vm::ProgramState::Stopped:
        return ProgramStatus::Stopped;
    case vm::ProgramState::Running:
        break;
    }
    return ProgramStatus::Started;
}

// CiA 302-3, 0x1F51: the transitions of the program's state machine.
AbortCode program_command(ProgramControlCommand command, ProgramStore& store, Plc& plc,
                          const ProgramStart& start) {
    const ProgramStatus status = program_status(plc);
    if (command == ProgramControlCommand::Clear) {
        return store.clear();
    }
    if (status == ProgramStatus::NoProgram) {
        return AbortCode::DeviceState;
    }
    switch (command) {
    case ProgramControlCommand::Stop:
        plc.runtime().stop();
        return AbortCode::None;
    case ProgramControlCommand::Start:
        if (status == ProgramStatus::Started) {
            return AbortCode::DeviceState;
        }
        return start(store.start_mode()) ? AbortCode::DeviceState : AbortCode::None;
    case ProgramControlCommand::Reset:
        plc.runtime().stop();
        store.reset();
        return AbortCode::None;
    case ProgramControlCommand::Clear:
        break;
    }
    return AbortCode::None;
}

} // namespace

void bind_program_download(canopen::ObjectDictionary& od, ProgramStore& store, Plc& plc,
                           ProgramStart start) {
    canopen::SubObject& data = *od.find(kProgramDataIndex, 1);
    data.on_read = [&store] {
        return store.image();
    };
    data.on_write = [&store](std::span<const std::uint8_t> image) {
        return store.download(image);
    };
    data.on_write_aborted = [&store](canopen::AbortCode reason) {
        store.interrupted(reason);
    };
    canopen::SubObject& control = *od.find(kCia302ProgramControlIndex, 1);
    control.on_read = [&plc] {
        return canopen::encode(static_cast<std::uint8_t>(program_status(plc)));
    };
    control.on_write = checked_write(
        std::move(control.on_write),
        [&store, &plc, start = std::move(start)](std::span<const std::uint8_t> value) {
            return program_command(static_cast<ProgramControlCommand>(value[0]), store, plc, start);
        });
    od.find(kProgramIdentificationIndex, 1)->on_read = [&store] {
        return canopen::encode(store.software_identification());
    };
    od.find(kFlashStatusIndex, 1)->on_read = [&store] {
        return canopen::encode(store.flash_status());
    };
}

} // namespace eposp::device
