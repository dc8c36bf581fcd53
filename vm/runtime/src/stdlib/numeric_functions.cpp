// IEC 61131-3 (3rd ed.) table 34 and 35: the numeric functions that are no opcode (ABS and SQRT
// are). One native per function and real type, named FUNCTION_REAL and FUNCTION_LREAL; integer
// arguments are converted to the real type by the caller. Results are IEEE 754: a domain error
// gives NaN and an overflow infinity, as on CODESYS targets with an FPU; no task is stopped.
// The functions themselves are vm/stdlib/real_functions.hpp's, which the compiler folds with.

#include "eposp/vm/stdlib/real_functions.hpp"
#include "library_parts.hpp"

namespace eposp::vm::stdlib {
namespace {

/// One native per function with a native row and real type: REAL's are the manifest's Base
/// variant (`SIN_REAL`), LREAL's the Wide (`SIN_LREAL`). The functions are the ones the compiler
/// folds constants with (vm/stdlib/real_functions.hpp).
template <typename F>
void add_real_functions(NativeRegistry& registry) {
    const Variant variant = sizeof(F) == 4 ? Variant::Base : Variant::Wide;
    for (const RealFunction<F>& function : kRealFunctions<F>) {
        const StandardFunction* row = find_standard_function(function.name);
        if (row->naming == NativeNaming::None) {
            continue; // SQRT: an opcode
        }
        if (function.unary != nullptr) {
            add_standard(
                registry, native_binding(*row, variant),
                [f = function.unary](NativeArgs& args) { args.set_result(f(args.get<F>(0))); });
        } else {
            add_standard(registry, native_binding(*row, variant),
                         [f = function.binary](NativeArgs& args) {
                             args.set_result(f(args.get<F>(0), args.get<F>(1)));
                         });
        }
    }
}

} // namespace

void register_numeric_functions(NativeRegistry& registry) {
    add_real_functions<float>(registry);
    add_real_functions<double>(registry);
}

} // namespace eposp::vm::stdlib
