#pragma once

// The parts register_standard_library is made of, one per kind of function.

#include "eposp/vm/native.hpp"
#include "eposp/vm/stdlib/manifest.hpp"

#include <utility>

namespace eposp::vm::stdlib {

/// Registers `function` under a standard function's binding: its name and signature are the
/// manifest's (vm/stdlib/manifest.hpp), which code generation calls it by.
inline void add_standard(NativeRegistry& registry, NativeBinding binding, NativeFunction function) {
    registry.add(std::move(binding.name), std::move(binding.signature), std::move(function));
}

void register_string_functions(NativeRegistry& registry);
void register_string_conversions(NativeRegistry& registry);
void register_numeric_functions(NativeRegistry& registry);
void register_time_functions(NativeRegistry& registry);
void register_wstring_functions(NativeRegistry& registry);

} // namespace eposp::vm::stdlib
