// IEC 61131-3 (3rd ed.) table 34 and 35: the numeric functions that are no opcode (ABS and SQRT
// are). One native per function and real type, named FUNCTION_REAL and FUNCTION_LREAL; integer
// arguments are converted to the real type by the caller. Results are IEEE 754: a domain error
// gives NaN and an overflow infinity, as on CODESYS targets with an FPU; no task is stopped.

#include "library_parts.hpp"

#include <cmath>

namespace eposp::vm::stdlib {
namespace {

/// REAL's natives are the manifest's Base variant (`SIN_REAL`), LREAL's the Wide (`SIN_LREAL`).
template <typename F>
NativeBinding real_binding(NativeFunctionName function) {
    return native_binding(function, sizeof(F) == 4 ? Variant::Base : Variant::Wide);
}

// The functions come in as captureless lambdas: taking the address of a std:: function is not
// allowed.
template <typename F>
void add_unary(NativeRegistry& registry, NativeFunctionName name, F (*function)(F)) {
    add_standard(registry, real_binding<F>(name),
                 [function](NativeArgs& args) { args.set_result(function(args.get<F>(0))); });
}

template <typename F>
void add_binary(NativeRegistry& registry, NativeFunctionName name, F (*function)(F, F)) {
    add_standard(registry, real_binding<F>(name), [function](NativeArgs& args) {
        args.set_result(function(args.get<F>(0), args.get<F>(1)));
    });
}

template <typename F>
void add_real_functions(NativeRegistry& registry) {
    add_unary<F>(registry, "LN", [](F x) { return std::log(x); });
    add_unary<F>(registry, "LOG", [](F x) { return std::log10(x); });
    add_unary<F>(registry, "EXP", [](F x) { return std::exp(x); });
    add_unary<F>(registry, "SIN", [](F x) { return std::sin(x); });
    add_unary<F>(registry, "COS", [](F x) { return std::cos(x); });
    add_unary<F>(registry, "TAN", [](F x) { return std::tan(x); });
    add_unary<F>(registry, "ASIN", [](F x) { return std::asin(x); });
    add_unary<F>(registry, "ACOS", [](F x) { return std::acos(x); });
    add_unary<F>(registry, "ATAN", [](F x) { return std::atan(x); });
    add_binary<F>(registry, "ATAN2", [](F y, F x) { return std::atan2(y, x); });
    // EXPT(IN1, IN2) = IN1 ** IN2; an integral IN2 of a negative IN1 is exact (pow is).
    add_binary<F>(registry, "EXPT", [](F base, F exponent) { return std::pow(base, exponent); });
}

} // namespace

void register_numeric_functions(NativeRegistry& registry) {
    add_real_functions<float>(registry);
    add_real_functions<double>(registry);
}

} // namespace eposp::vm::stdlib
