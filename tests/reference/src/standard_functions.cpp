// The standard functions (IEC 61131-3 ed. 3, tables 22-36) and the type conversions, from their
// definitions; REAL to integer rounds to the nearest integer, ties to even (IEC 60559, as the
// standard's 6.6.2.5.3 asks), TRUNC truncates.

#include "eposp/vm/stdlib/manifest.hpp"
#include "evaluator.hpp"

#include <cfenv>
#include <cmath>
#include <functional>

namespace eposp::reference {

using E = ast::ElementaryType;

namespace {

constexpr std::int64_t kNsPerMs = 1'000'000;
constexpr std::int64_t kNsPerS = 1'000'000'000;

double math(const std::string& name, double x) {
    static const std::map<std::string, double (*)(double)> functions = {
        {"SQRT",
         [](double v) {
             return std::sqrt(v);
         }},
        {"LN",
         [](double v) {
             return std::log(v);
         }},
        {"LOG",
         [](double v) {
             return std::log10(v);
         }},
        {"EXP",
         [](double v) {
             return std::exp(v);
         }},
        {"SIN",
         [](double v) {
             return std::sin(v);
         }},
        {"COS",
         [](double v) {
             return std::cos(v);
         }},
        {"TAN",
         [](double v) {
             return std::tan(v);
         }},
        {"ASIN",
         [](double v) {
             return std::asin(v);
         }},
        {"ACOS",
         [](double v) {
             return std::acos(v);
         }},
        {"ATAN",
         [](double v) {
             return std::atan(v);
         }},
    };
    return functions.at(name)(x);
}

float math(const std::string& name, float x) {
    static const std::map<std::string, float (*)(float)> functions = {
        {"SQRT",
         [](float v) {
             return std::sqrt(v);
         }},
        {"LN",
         [](float v) {
             return std::log(v);
         }},
        {"LOG",
         [](float v) {
             return std::log10(v);
         }},
        {"EXP",
         [](float v) {
             return std::exp(v);
         }},
        {"SIN",
         [](float v) {
             return std::sin(v);
         }},
        {"COS",
         [](float v) {
             return std::cos(v);
         }},
        {"TAN",
         [](float v) {
             return std::tan(v);
         }},
        {"ASIN",
         [](float v) {
             return std::asin(v);
         }},
        {"ACOS",
         [](float v) {
             return std::acos(v);
         }},
        {"ATAN",
         [](float v) {
             return std::atan(v);
         }},
    };
    return functions.at(name)(x);
}

std::int64_t position(const Value& value) {
    return signed_type(*value.type)
               ? value.as_signed()
               : static_cast<std::int64_t>(std::min<std::uint64_t>(value.bits, INT64_MAX));
}

} // namespace

Value Evaluator::standard_function(const types::CallTarget& target,
                                   const ast::CallExpression& node) {
    const std::string& name = target.name;
    std::vector<Value> in;
    for (const ast::Argument* argument : types::standard_arguments(name, node)) {
        in.push_back(eval(*argument->value));
    }
    const sema::Type& result = *target.result;
    const sema::Type* operand = target.operand;
    // An input is stored into the function's input of the overload's type, so it is cut there
    // like any stored value, then computed in the operand's working type.
    const auto as = [&](const Value& value) {
        return widen(store(value, *operand), working(*operand));
    };
    if (name == "MOVE") {
        return in[0];
    }
    if (name == "ABS") {
        const Value v = as(in[0]);
        if (shape_of(*v.type) == Shape::Integer) {
            return signed_type(*v.type) && v.as_signed() < 0 ? integer(*v.type, 0 - v.bits) : v;
        }
        return real(*v.type, std::fabs(v.real));
    }
    if (name == "SQRT" || name == "LN" || name == "LOG" || name == "EXP" || name == "SIN" ||
        name == "COS" || name == "TAN" || name == "ASIN" || name == "ACOS" || name == "ATAN") {
        const Value v = as(in[0]);
        if (result.elementary == E::Real) {
            return real(result, static_cast<double>(math(name, static_cast<float>(v.real))));
        }
        return real(result, math(name, v.real));
    }
    if (name == "ATAN2") {
        const Value y = as(in[0]);
        const Value x = as(in[1]);
        if (result.elementary == E::Real) {
            return real(result, static_cast<double>(std::atan2(static_cast<float>(y.real),
                                                               static_cast<float>(x.real))));
        }
        return real(result, std::atan2(y.real, x.real));
    }
    if (name == "EXPT") {
        return power(as(in[0]), widen(in[1], result), result);
    }
    using Op = ast::BinaryOperator;
    static const std::map<std::string, Op> arithmetic_ops = {{"ADD", Op::Add},
                                                             {"MUL", Op::Multiply},
                                                             {"SUB", Op::Subtract},
                                                             {"DIV", Op::Divide},
                                                             {"MOD", Op::Modulo}};
    if (const auto op = arithmetic_ops.find(name); op != arithmetic_ops.end()) {
        Value total = as(in[0]);
        for (std::size_t i = 1; i < in.size(); ++i) {
            total = arithmetic(op->second, total, as(in[i]), working(*operand));
        }
        return total;
    }
    if (name == "AND" || name == "OR" || name == "XOR" || name == "NOT") {
        Value total = widen(in[0], *operand);
        if (name == "NOT") {
            return integer(*operand, operand->elementary == E::Bool ? total.bits ^ 1 : ~total.bits);
        }
        for (std::size_t i = 1; i < in.size(); ++i) {
            const std::uint64_t bits = widen(in[i], *operand).bits;
            total = integer(*operand, name == "AND"  ? total.bits & bits
                                      : name == "OR" ? total.bits | bits
                                                     : total.bits ^ bits);
        }
        return total;
    }
    static const std::map<std::string, Op> comparisons = {
        {"GT", Op::Greater},   {"GE", Op::GreaterEqual}, {"EQ", Op::Equal},
        {"LE", Op::LessEqual}, {"LT", Op::Less},         {"NE", Op::NotEqual}};
    if (const auto op = comparisons.find(name); op != comparisons.end()) {
        // Extensible comparisons hold for each neighbouring pair (table 28).
        bool all = true;
        for (std::size_t i = 1; i < in.size(); ++i) {
            all = all && compare(op->second, as(in[i - 1]), as(in[i]));
        }
        return integer(result, all ? 1 : 0);
    }
    if (name == "MAX" || name == "MIN") {
        Value best = as(in[0]);
        for (std::size_t i = 1; i < in.size(); ++i) {
            const Value v = as(in[i]);
            const int c = order(v, best);
            if (name == "MAX" ? c > 0 : c < 0) {
                best = v;
            }
        }
        return best;
    }
    if (name == "LIMIT") {
        const Value low = as(in[0]);
        const Value high = as(in[2]);
        Value v = as(in[1]);
        if (order(v, low) < 0) {
            v = low;
        }
        return order(v, high) > 0 ? high : v;
    }
    if (name == "SEL") {
        return as(in[0].bits != 0 ? in[2] : in[1]);
    }
    if (name == "MUX") {
        const std::int64_t k = position(in[0]);
        if (k < 0 || static_cast<std::size_t>(k) + 1 >= in.size()) {
            throw Unsupported("MUX with K outside its inputs");
        }
        return as(in[static_cast<std::size_t>(k) + 1]);
    }
    if (name == "SHL" || name == "SHR" || name == "ROL" || name == "ROR") {
        const sema::Type& type = *operand;
        const unsigned width = width_of(type);
        // The count taken as unsigned, a negative one as its 64-bit two's complement
        // (docs/st-language.md): SHL and SHR by at least the width give 0.
        const std::uint64_t n = in[1].bits;
        const std::uint64_t mask =
            width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1;
        const std::uint64_t bits = widen(in[0], type).bits & mask;
        if (name == "SHR" && signed_type(type)) {
            throw Unsupported("SHR of a signed integer (arithmetic or logical is not defined)");
        }
        if (name == "SHL" || name == "SHR") {
            if (n >= width) {
                return integer(type, 0);
            }
            return integer(type, name == "SHL" ? bits << n : bits >> n);
        }
        const unsigned r = static_cast<unsigned>(n % width);
        if (r == 0) {
            return integer(type, bits);
        }
        const unsigned l = name == "ROL" ? r : width - r;
        return integer(type, ((bits << l) | (bits >> (width - l))) & mask);
    }
    if (name == "LOWER_BOUND" || name == "UPPER_BOUND") {
        const std::int64_t d = position(in[1]);
        if (d < 1 || static_cast<std::size_t>(d) > in[0].type->dimensions.size()) {
            throw Unsupported("a bound of a dimension the array does not have");
        }
        const sema::ArrayDimension& bounds =
            in[0].type->dimensions[static_cast<std::size_t>(d - 1)];
        return integer(result, static_cast<std::uint64_t>(name == "LOWER_BOUND"
                                                              ? bounds.lower
                                                              : bounds.lower + bounds.count - 1));
    }
    // Table 30, short and long forms alike (every time is nanoseconds in 64 bits), as their
    // operators compute; ADD and MUL are extensible (table 24), from left to right.
    const vm::stdlib::StandardFunction* row = vm::stdlib::find_standard_function(name);
    if (row != nullptr && row->family == vm::stdlib::Family::Time) {
        using vm::stdlib::Operation;
        // CONCAT_DATE_TOD adds too: DATE and TOD are nanoseconds since 1970 and since midnight.
        const Op op = row->operation == Operation::Add        ? Op::Add
                      : row->operation == Operation::Subtract ? Op::Subtract
                      : row->operation == Operation::Multiply ? Op::Multiply
                                                              : Op::Divide;
        Value value = in[0];
        for (std::size_t i = 1; i < in.size(); ++i) {
            value = time_arithmetic(op, value, in[i], result);
        }
        return value;
    }
    return string_function(name, in, result);
}

Value Evaluator::string_function(const std::string& name, const std::vector<Value>& in,
                                 const sema::Type& result) {
    // Table 36; positions count from 1. Where the standard leaves a case open (a position
    // outside the string, a negative length) the evaluator refuses rather than guesses.
    const auto length = [](const Value& value) {
        const std::int64_t l = position(value);
        if (l < 0) {
            throw Unsupported("a negative string length");
        }
        return static_cast<std::size_t>(l);
    };
    const auto at = [](const Value& value, std::size_t size, std::size_t first) {
        const std::int64_t p = position(value);
        if (p < static_cast<std::int64_t>(first) || p > static_cast<std::int64_t>(size)) {
            throw Unsupported("a string position outside the string");
        }
        return static_cast<std::size_t>(p);
    };
    const std::string& s = in[0].text;
    if (name == "LEN") {
        return integer(result, s.size());
    }
    if (name == "LEFT") {
        return text(result, s.substr(0, length(in[1])));
    }
    if (name == "RIGHT") {
        const std::size_t l = std::min(length(in[1]), s.size());
        return text(result, s.substr(s.size() - l));
    }
    if (name == "MID") {
        const std::size_t l = length(in[1]);
        return text(result, s.substr(at(in[2], s.size(), 1) - 1, l));
    }
    if (name == "CONCAT") {
        std::string joined;
        for (const Value& v : in) {
            joined += v.text;
        }
        return text(result, joined);
    }
    if (name == "INSERT") {
        const std::size_t p = at(in[2], s.size(), 0);
        return text(result, s.substr(0, p) + in[1].text + s.substr(p));
    }
    if (name == "DELETE") {
        std::string copy = s;
        copy.erase(at(in[2], s.size(), 1) - 1, length(in[1]));
        return text(result, copy);
    }
    if (name == "REPLACE") {
        std::string copy = s;
        copy.replace(at(in[3], s.size(), 1) - 1, length(in[2]), in[1].text);
        return text(result, copy);
    }
    if (name == "FIND") {
        if (in[1].text.empty()) {
            throw Unsupported("FIND of an empty string");
        }
        const std::size_t found = s.find(in[1].text);
        return integer(result, found == std::string::npos ? 0 : found + 1);
    }
    throw Unsupported("the standard function " + name);
}

// Conversions the standard leaves open (from strings, between REAL and TIME or BOOL) were
// refused before running (support_check.cpp).
Value Evaluator::conversion(const types::CallTarget& target, const Value& value) {
    const sema::Type& from = *target.operand;
    const sema::Type& to = *target.result;
    const Shape source = shape_of(from);
    const Shape result = shape_of(to);
    if (result == Shape::String && is_decimal(from)) {
        // An integer's decimal digits, with a sign when negative: the one string form of a
        // number that leaves nothing to choose.
        return text(to, signed_type(from) ? std::to_string(value.as_signed())
                                          : std::to_string(value.bits));
    }
    const bool real_source = source == Shape::Real || source == Shape::Lreal;
    const bool real_result = result == Shape::Real || result == Shape::Lreal;
    if (real_source && real_result) {
        return real(to, value.real);
    }
    if (real_result) {
        return widen(integer(from, value.bits), to);
    }
    if (real_source) {
        double whole = target.name == "TRUNC" ? std::trunc(value.real) : std::nearbyint(value.real);
        const auto range = ast::integer_range(to.elementary);
        if (std::isnan(whole) || whole < static_cast<double>(range->min) ||
            whole >= std::ldexp(static_cast<double>((range->max >> 1) + 1), 1)) {
            throw Unsupported("a real number outside the range of " + to.name);
        }
        return integer(to, whole < 0 ? static_cast<std::uint64_t>(static_cast<std::int64_t>(whole))
                                     : static_cast<std::uint64_t>(whole));
    }
    // Integers, bit strings, BOOL, times and dates.
    const auto unit = [](E e) -> std::int64_t {
        switch (e) {
        case E::Time:
        case E::TimeOfDay:
            return kNsPerMs; // TIME_TO_<number> in ms, as docs/st-language.md says
        case E::Date:
        case E::DateAndTime:
            return kNsPerS;
        case E::Ltime:
            return 1;
        default:
            return 0;
        }
    };
    const bool time_source = sema::is_time_like(from);
    const bool time_result = sema::is_time_like(to);
    if (time_source && time_result) {
        // A date is a day at midnight and a time of day is since midnight, whatever it is made
        // of, also before 1970 (DT_TO_DATE, DT_TO_TOD, vm/README.md); the rest keep the value.
        const bool to_date = to.elementary == E::Date || to.elementary == E::Ldate;
        const bool to_time_of_day = to.elementary == E::TimeOfDay || to.elementary == E::Ltod;
        const auto same_kind = [&](E a, E b) {
            return from.elementary == a || from.elementary == b;
        };
        if (to_date && !same_kind(E::Date, E::Ldate)) {
            return integer(to, static_cast<std::uint64_t>(value.as_signed() -
                                                          since_midnight(value.as_signed())));
        }
        if (to_time_of_day && !same_kind(E::TimeOfDay, E::Ltod)) {
            return integer(to, static_cast<std::uint64_t>(since_midnight(value.as_signed())));
        }
        return integer(to, value.bits);
    }
    if (time_source || time_result) {
        const std::int64_t scale = unit(time_source ? from.elementary : to.elementary);
        if (scale == 0 || (time_source ? to : from).elementary == E::Bool) {
            throw Unsupported("the conversion " + target.name);
        }
        if (time_source) {
            return integer(to, static_cast<std::uint64_t>(value.as_signed() / scale));
        }
        return integer(to, value.bits * static_cast<std::uint64_t>(scale));
    }
    return integer(to, value.bits);
}

} // namespace eposp::reference
