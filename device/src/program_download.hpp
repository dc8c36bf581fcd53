#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/device/plc.hpp"
#include "plc_objects.hpp"
#include "program_store.hpp"

namespace eposp::device {

/// Binds the CiA 302-3 program objects to the program store and the PLC
/// (docs/service-interface.md, "Program download and program control"):
/// - 0x1F50 sub 1: a write is a download (ProgramStore::download); a read gives the stored image.
/// - 0x1F51 sub 1 reads the program's state: 0 stopped, 1 started, 3 no program. Writing 0 stops
///   it, 1 starts it (ProgramStore::start_mode(), by `start`, which boots the networks), 2 resets
///   it (stops it; the next start is cold), 3 clears it. A command the state does not allow is
///   refused with DeviceState (0x08000022): anything but clear without a program, start while
///   started, clear while started.
/// - 0x1F56 and 0x1F57 read the store's identification and flash status.
/// `od`, `store` and `plc` must outlive the hooks.
void bind_program_download(canopen::ObjectDictionary& od, ProgramStore& store, Plc& plc,
                           ProgramStart start);

} // namespace eposp::device
