// Compiled by CTest only, never built: naming a row of the standard-library manifest that does
// not exist, or one that has no native, must not compile (vm/stdlib/manifest.hpp,
// NativeFunctionName). The test passes when the compiler's error names the reason.
#include "eposp/vm/stdlib/manifest.hpp"

eposp::vm::stdlib::NativeBinding misnamed() {
#ifdef EPOSP_MISSPELT
    return eposp::vm::stdlib::native_binding("MUL_TIM");
#else
    return eposp::vm::stdlib::native_binding("ADD"); // inline: opcodes, no native
#endif
}
