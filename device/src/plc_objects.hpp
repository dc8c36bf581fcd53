#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/device/error_entry.hpp"
#include "eposp/device/plc.hpp"

#include <cstdint>
#include <functional>
#include <optional>

namespace eposp::device {

/// Binds the PLC to the dictionary (10.37, 10.38 - 10.49, 10.10, 10.2 - 10.4):
/// - 0x5F51 reads the program's state (0 stopped, else the mode it started in); writing 1, 2 or
///   3 starts the program cold, warm or hot, 0 stops it. Without a program, or starting one that
///   runs, the write is refused (DeviceState, 0x08000022). Starting is `start`'s job (the
///   device boots its networks with it).
/// - 0xA000 - 0xA200 are the PLC's inputs: a value written (SDO or RPDO) goes into its input
///   image. 0xA400 - 0xA680 read its output image (so TPDOs send what the program wrote).
/// - 0x1011 "load" and "eras" are refused while the program runs (firmware 0110h).
/// - The PLC's errors go to the error history, port code 0, node-ID 0.
/// `od` and `plc` must outlive the hooks.
using ProgramStart = std::function<std::optional<core::Error>(vm::StartMode mode)>;
void bind_plc(canopen::ObjectDictionary& od, Plc& plc, ProgramStart start);

/// A write hook that runs the entry's own check (its value list, range rule) before `action`:
/// a device binds its behaviour to an entry without losing the entry's rule.
canopen::SubObject::WriteHook checked_write(canopen::SubObject::WriteHook check,
                                            canopen::SubObject::WriteHook action);

/// For 0x1011: refused while the program runs.
canopen::AbortCode restore_permitted(const Plc& plc);

} // namespace eposp::device
