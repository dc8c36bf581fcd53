#pragma once

#include "eposp/vm/native.hpp"

namespace eposp::vm::stdlib {

/// Registers the IEC 61131-3 standard functions that are not single opcodes: the string
/// functions, *_TO_STRING / STRING_TO_*, the transcendental functions and the time and date
/// arithmetic that needs more than an add. Names and argument conventions: vm/README.md,
/// "Standard library".
void register_standard_library(NativeRegistry& registry);

} // namespace eposp::vm::stdlib
