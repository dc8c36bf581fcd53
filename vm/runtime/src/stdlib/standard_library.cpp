#include "eposp/vm/stdlib/standard_library.hpp"

#include "library_parts.hpp"

namespace eposp::vm::stdlib {

void register_standard_library(NativeRegistry& registry) {
    register_string_functions(registry);
    register_string_conversions(registry);
    register_numeric_functions(registry);
    register_time_functions(registry);
    register_wstring_functions(registry);
}

} // namespace eposp::vm::stdlib
