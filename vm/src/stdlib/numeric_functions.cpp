// IEC 61131-3 (3rd ed.) table 34 and 35: the numeric functions that are no opcode (ABS and SQRT
// are). One native per function and real type, named FUNCTION_REAL and FUNCTION_LREAL; integer
// arguments are converted to the real type by the caller. Results are IEEE 754: a domain error
// gives NaN and an overflow infinity, as on CODESYS targets with an FPU; no task is stopped.

#include "library_parts.hpp"

#include <cmath>
#include <string>

namespace eposp::vm::stdlib {
namespace {

template <typename F>
constexpr Scalar real_scalar() {
    return sizeof(F) == 4 ? Scalar::F32 : Scalar::F64;
}

template <typename F>
std::string real_name(const char* function) {
    return std::string(function) + (sizeof(F) == 4 ? "_REAL" : "_LREAL");
}

template <typename F, F (*function)(F)>
void add_unary(NativeRegistry& registry, const char* name) {
    constexpr auto s = real_scalar<F>();
    registry.add(real_name<F>(name), {true, s, {s}},
                 [](NativeArgs& args) { args.set_result(function(args.get<F>(0))); });
}

template <typename F, F (*function)(F, F)>
void add_binary(NativeRegistry& registry, const char* name) {
    constexpr auto s = real_scalar<F>();
    registry.add(real_name<F>(name), {true, s, {s, s}}, [](NativeArgs& args) {
        args.set_result(function(args.get<F>(0), args.get<F>(1)));
    });
}

template <typename F>
void add_real_functions(NativeRegistry& registry) {
    add_unary<F, static_cast<F (*)(F)>(std::log)>(registry, "LN");
    add_unary<F, static_cast<F (*)(F)>(std::log10)>(registry, "LOG");
    add_unary<F, static_cast<F (*)(F)>(std::exp)>(registry, "EXP");
    add_unary<F, static_cast<F (*)(F)>(std::sin)>(registry, "SIN");
    add_unary<F, static_cast<F (*)(F)>(std::cos)>(registry, "COS");
    add_unary<F, static_cast<F (*)(F)>(std::tan)>(registry, "TAN");
    add_unary<F, static_cast<F (*)(F)>(std::asin)>(registry, "ASIN");
    add_unary<F, static_cast<F (*)(F)>(std::acos)>(registry, "ACOS");
    add_unary<F, static_cast<F (*)(F)>(std::atan)>(registry, "ATAN");
    add_binary<F, static_cast<F (*)(F, F)>(std::atan2)>(registry, "ATAN2");
    // EXPT(IN1, IN2) = IN1 ** IN2; an integral IN2 of a negative IN1 is exact (pow is).
    add_binary<F, static_cast<F (*)(F, F)>(std::pow)>(registry, "EXPT");
}

} // namespace

void register_numeric_functions(NativeRegistry& registry) {
    add_real_functions<float>(registry);
    add_real_functions<double>(registry);
}

} // namespace eposp::vm::stdlib
