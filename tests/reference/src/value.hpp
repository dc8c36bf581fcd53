#pragma once

// A value of the reference evaluator: one variable's contents as the standard describes them,
// not as the VM lays them out (no byte offsets, no headers).

#include "eposp/compiler/sema/type.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace eposp::reference {

namespace sema = compiler::sema;

/// How a type's values are held.
enum class Shape { Integer, Real, Lreal, String, Array, Record, Unsupported };

/// A value of any IEC type. Integers, bit strings, BOOL, CHAR, times, dates and enumeration
/// values are held in `bits`, sign-extended (signed types) or zero-extended (the others) from
/// their width; REAL in `real` (always a float's value), LREAL in `real`; STRING in `text`;
/// arrays (row-major) and structures or FB instances in `elements` (with `names`, folded).
struct Value {
    const sema::Type* type = nullptr;
    std::uint64_t bits = 0;
    double real = 0.0;
    std::string text{};
    std::vector<Value> elements{};
    std::vector<std::string> names{};

    /// The member `name` (folded) of a structure or instance; null if it has none.
    Value* member(const std::string& folded);
    const Value* member(const std::string& folded) const;
    std::int64_t as_signed() const { return static_cast<std::int64_t>(bits); }
};

/// A run-time fault: the text the VM gives (`division by zero`), without the place.
struct Fault : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// A construct the evaluator does not model: it refuses rather than guesses.
struct Unsupported : std::runtime_error {
    explicit Unsupported(const std::string& what)
        : std::runtime_error("not supported by the reference evaluator: " + what) {}
};

Shape shape_of(const sema::Type& type);
/// The width in bits of an integer-shaped type and whether it is signed.
unsigned width_of(const sema::Type& type);
bool signed_type(const sema::Type& type);
/// ANY_INT: the types whose `_TO_STRING` is their decimal digits.
bool is_decimal(const sema::Type& type);
/// `raw` cut to `width` bits and extended back to 64 the way a type of that width holds it.
std::uint64_t wrap(std::uint64_t raw, unsigned width, bool is_signed);
/// `value` as the integer type `type` holds it (wrapping at its width).
Value integer(const sema::Type& type, std::uint64_t raw);
Value real(const sema::Type& type, double value);
Value text(const sema::Type& type, std::string value);
/// The time of day of a count of nanoseconds since a midnight, also before it (vm/README.md).
std::int64_t since_midnight(std::int64_t ns);

} // namespace eposp::reference
