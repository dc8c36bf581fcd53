#pragma once

// IEC 61131-3 (3rd ed.) table 23 and 24: the numeric functions of a real argument, as the VM
// computes them in REAL (F = float) and LREAL (F = double). The VM's natives (LN_REAL,
// EXPT_LREAL...) are these; the compiler folds a call of constants with the same ones, so a
// constant is the value the same call gives at run time. Results are IEEE 754: a domain error
// gives NaN and an overflow infinity; no task is stopped.

#include <array>
#include <cmath>
#include <string_view>

namespace eposp::vm::stdlib {

template <typename F>
struct RealFunction {
    std::string_view name;
    F (*unary)(F) = nullptr;     ///< one input: SQRT, LN...
    F (*binary)(F, F) = nullptr; ///< two inputs: ATAN2(Y, X), EXPT(IN1, IN2)
};

// Captureless lambdas: taking the address of a std:: function is not allowed.
template <typename F>
inline constexpr std::array<RealFunction<F>, 12> kRealFunctions{{
    // SQRT is the Sqrt opcode, whose result IEEE 754 defines exactly (correctly rounded).
    {"SQRT",
     [](F x) {
         return std::sqrt(x);
     }},
    {"LN",
     [](F x) {
         return std::log(x);
     }},
    {"LOG",
     [](F x) {
         return std::log10(x);
     }},
    {"EXP",
     [](F x) {
         return std::exp(x);
     }},
    {"SIN",
     [](F x) {
         return std::sin(x);
     }},
    {"COS",
     [](F x) {
         return std::cos(x);
     }},
    {"TAN",
     [](F x) {
         return std::tan(x);
     }},
    {"ASIN",
     [](F x) {
         return std::asin(x);
     }},
    {"ACOS",
     [](F x) {
         return std::acos(x);
     }},
    {"ATAN",
     [](F x) {
         return std::atan(x);
     }},
    {"ATAN2", nullptr,
     [](F y, F x) {
         return std::atan2(y, x);
     }},
    // EXPT(IN1, IN2) = IN1 ** IN2; an integral IN2 of a negative IN1 is exact (pow is).
    {"EXPT", nullptr,
     [](F base, F exponent) {
         return std::pow(base, exponent);
     }},
}};

/// The real function named `name` (upper case), if it is one of table 23-24.
template <typename F>
constexpr const RealFunction<F>* find_real_function(std::string_view name) {
    for (const RealFunction<F>& function : kRealFunctions<F>) {
        if (function.name == name) {
            return &function;
        }
    }
    return nullptr;
}

} // namespace eposp::vm::stdlib
