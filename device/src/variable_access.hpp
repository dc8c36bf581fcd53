#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/device/plc.hpp"

namespace eposp::device {

/// Binds eposp's variable access object 0x5F60 to the PLC, so that a service tool (`eposp
/// watch`) reads, writes and forces the program's variables by path over any link that reaches
/// the dictionary (docs/service-interface.md, "Variable access"):
/// - sub 1 (VISIBLE_STRING): the path, e.g. `Main.counter`; a path the program does not have is
///   refused with InvalidValue (0x06090030).
/// - sub 2 (VISIBLE_STRING): reads the value as an IEC literal (empty when the path names
///   nothing); writing a literal sets the variable once (parse_value).
/// - sub 3 (VISIBLE_STRING): writing a literal forces the variable; reads its value while it is
///   forced, empty otherwise.
/// - sub 4 (UNSIGNED8, write only): any value releases the force (a variable not forced stays
///   as it is).
/// Without a program every access but reading is refused with DeviceState (0x08000022); a path
/// that names nothing since the last download with TransferOrStore (0x08000020); a read-only
/// variable with ReadOnly (0x06010002); a literal that is no value of the variable's type (or
/// outside its subrange) with InvalidValue (0x06090030). `od` and `plc` must outlive the hooks.
void bind_variable_access(canopen::ObjectDictionary& od, Plc& plc);

} // namespace eposp::device
