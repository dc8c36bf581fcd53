#pragma once

// The parts register_standard_library is made of, one per kind of function.

#include "eposp/vm/native.hpp"

namespace eposp::vm::stdlib {

void register_string_functions(NativeRegistry& registry);
void register_string_conversions(NativeRegistry& registry);
void register_numeric_functions(NativeRegistry& registry);
void register_time_functions(NativeRegistry& registry);
void register_wstring_functions(NativeRegistry& registry);

} // namespace eposp::vm::stdlib
