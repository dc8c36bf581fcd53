#include "eposp/differential/st_generator.hpp"

#include "checksum_functions.hpp"
#include "st_types.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace eposp::differential {
namespace {

// The characters of generated strings: MixS (checksum_functions.cpp) folds each by its
// position in this alphabet.
constexpr const char* kAlphabet = kStringAlphabet;

/// Somewhere a value lives: a scalar (`v3`, `st0.a`, `fb0.q`), or the elements of an array
/// (`a2[i, j]`, `as0[i].b`).
struct Place {
    std::string name;
    Ty type = Ty::Dint;
    int capacity = 0;                      // STRING[capacity]
    std::vector<std::pair<int, int>> dims; // (lower bound, element count) per dimension
    std::string member;                    // `.b` after the index of an array of structs
    bool writable = true;
};

Place scalar(std::string name, Ty type, int capacity, bool writable) {
    Place place;
    place.name = std::move(name);
    place.type = type;
    place.capacity = capacity;
    place.writable = writable;
    return place;
}

struct Param {
    std::string name;
    Ty type = Ty::Dint;
    int capacity = 0;
};

struct Function {
    std::string name;
    Ty result = Ty::Dint;
    int capacity = 0;
    std::vector<Param> inputs;
    std::optional<Param> in_out;
};

struct FunctionBlock {
    std::string name;
    std::vector<Param> inputs;
    std::vector<Param> outputs;
};

/// What statements of one POU body may use.
struct Scope {
    std::vector<Place> places;
    bool main = false;                     // Main folds what it assigns into the checksum
    int loops = 0;                         // enclosing loops (EXIT and CONTINUE need one)
    int counters = 0;                      // loop counters declared so far (c0, c1, ...)
    std::vector<std::string> fb_instances; // instances callable here, by index into blocks_
    std::vector<std::size_t> fb_types;
};

class Generator {
public:
    Generator(std::mt19937_64& random, const GeneratorOptions& options)
        : random_(random), options_(options) {}

    GeneratedProgram run();

private:
    // --- randomness
    int below(int n) { return static_cast<int>(random_() % static_cast<std::uint64_t>(n)); }
    bool chance(int percent) { return below(100) < percent; }
    template <typename T>
    const T& one_of(const std::vector<T>& items) {
        return items[static_cast<std::size_t>(below(static_cast<int>(items.size())))];
    }

    // --- types and literals
    Ty any_scalar_type();
    Ty any_integer_type() { return kIntegerTypes[static_cast<std::size_t>(below(12))]; }
    Ty index_type() { return chance(50) ? Ty::Udint : Ty::Ulint; }
    std::string literal(Ty type, int max_length = 6);
    std::string integer_literal(Ty type);
    std::string string_literal(int max_length);
    int string_capacity() { return std::array{4, 8, 16, 24}[static_cast<std::size_t>(below(4))]; }

    // --- expressions
    Expr expr(Ty type, int depth, int max_length = 80);
    std::optional<Expr> read(Ty type, int depth, int max_length);
    Expr access(const Place& place, int depth, std::string replacement);
    Expr signed_expr(Ty type, int depth);
    Expr unsigned_expr(Ty type, int depth);
    /// `value`, an operation of a type narrower than DINT, kept within its type.
    Expr in_range(Ty type, Expr value);
    Expr bit_string_expr(Ty type, int depth);
    Expr bool_expr(int depth);
    Expr real_expr(Ty type, int depth);
    /// A TIME from table 30's arithmetic on durations, times of day and dates and times.
    Expr duration(int depth);
    Expr string_expr(int depth, int max_length);
    std::optional<Expr> selection(Ty type, int depth, int max_length);
    std::optional<Expr> call(Ty type, int depth, int max_length);
    Expr conversion_to(Ty type, int depth);
    /// An operator expression over literals and the constants of the scope: one the compiler
    /// evaluates at compile time (no call, no variable).
    Expr constant_expr(Ty type, int depth);
    Expr real_to_integer(Ty type, int depth);
    Expr arguments_call(const Function& function, int depth);

    // --- statements
    Block statements(Scope& scope, int count, int depth);
    void one_statement(Scope& scope, int depth, Block& out);
    void assignment(Scope& scope, Block& out);
    void if_statement(Scope& scope, int depth, Block& out);
    void case_statement(Scope& scope, int depth, Block& out);
    void for_statement(Scope& scope, int depth, Block& out);
    void while_statement(Scope& scope, int depth, Block& out, bool repeat);
    void loop_exit(Block& out);
    void fb_call(Scope& scope, Block& out);
    void in_out_call(Scope& scope, Block& out);
    void fold(const Scope& scope, const Expr& value, Ty type, Block& out);
    std::string counter(Scope& scope);

    // --- declarations
    std::vector<Place> declare_variables(const std::string& prefix, int count, Block& decls,
                                         bool initialise);
    Stmt declaration(const std::string& name, const std::string& type_text,
                     const std::string& initial);
    std::string declare_type(Ty type, int capacity);
    void struct_types(Block& program);
    void function(Block& program);
    void function_block(Block& program);
    std::vector<Place> declare_constants(Block& decls);
    void main_program(Block& program);
    void final_folds(Scope& scope, Block& body);

    std::mt19937_64& random_;
    const GeneratorOptions& options_;
    std::vector<Function> functions_;
    std::vector<FunctionBlock> blocks_;
    struct StructType {
        std::string name;
        std::vector<Param> members;
    };
    std::vector<StructType> structs_;
    Scope* scope_ = nullptr; // the POU body being generated: what expressions may read
    int names_ = 0;
};

// ---------------------------------------------------------------- types and literals

Ty Generator::any_scalar_type() {
    for (;;) {
        const auto type = static_cast<Ty>(below(16));
        if ((is_real(type) && !options_.reals) || (type == Ty::String && !options_.strings)) {
            continue;
        }
        return type;
    }
}

std::string Generator::integer_literal(Ty type) {
    const int bits = bits_of(type);
    std::string value;
    switch (below(7)) {
    case 0:
        value = "0";
        break;
    case 1:
        value = "1";
        break;
    case 2:
        value = min_text(type);
        break;
    case 3:
        value = max_text(type);
        break;
    case 4:
        value = is_signed(type) ? "-1" : "2";
        break;
    case 5:
        value = std::to_string(below(100) - (is_signed(type) ? 50 : 0));
        break;
    default: {
        const std::uint64_t raw = bits == 64 ? random_() : random_() & ((1ULL << bits) - 1);
        if (is_signed(type)) {
            const auto shift = static_cast<unsigned>(64 - bits);
            value = std::to_string(static_cast<std::int64_t>(raw << shift) >> shift);
        } else if (is_bit_string(type)) {
            char hex[24];
            std::snprintf(hex, sizeof hex, "16#%llX", static_cast<unsigned long long>(raw));
            value = hex;
        } else {
            value = std::to_string(raw);
        }
    }
    }
    return type_name(type) + "#" + value;
}

std::string Generator::string_literal(int max_length) {
    const int length = below(std::min(max_length, 6) + 1);
    std::string text = "'";
    for (int i = 0; i < length; ++i) {
        text += kAlphabet[below(static_cast<int>(std::string_view(kAlphabet).size()))];
    }
    return text + "'";
}

std::string Generator::literal(Ty type, int max_length) {
    switch (type) {
    case Ty::Bool:
        return chance(50) ? "TRUE" : "FALSE";
    case Ty::String:
        return string_literal(max_length);
    case Ty::Real:
    case Ty::Lreal: {
        // Eighths are exact in binary and short in decimal.
        char text[48];
        const int magnitude =
            std::array{100, 10'000, 1'000'000}[static_cast<std::size_t>(below(3))];
        std::snprintf(text, sizeof text, "%.3f", (below(2 * magnitude) - magnitude) / 8.0);
        return type_name(type) + "#" + text;
    }
    default:
        return integer_literal(type);
    }
}

// ---------------------------------------------------------------- expressions

Expr Generator::expr(Ty type, int depth, int max_length) {
    if (depth <= 0 || chance(20)) {
        if (auto value = read(type, depth, max_length); value && chance(75)) {
            return std::move(*value);
        }
        return leaf(literal(type, max_length), one_literal(type));
    }
    if (chance(10)) {
        if (auto value = call(type, depth, max_length)) {
            return std::move(*value);
        }
    }
    if (chance(15)) {
        if (auto value = selection(type, depth, max_length)) {
            return std::move(*value);
        }
    }
    if (type != Ty::String && chance(20)) {
        return conversion_to(type, depth);
    }
    switch (type) {
    case Ty::Bool:
        return bool_expr(depth);
    case Ty::Real:
    case Ty::Lreal:
        return real_expr(type, depth);
    case Ty::String:
        return string_expr(depth, max_length);
    default:
        return is_signed(type)     ? signed_expr(type, depth)
               : is_unsigned(type) ? unsigned_expr(type, depth)
                                   : bit_string_expr(type, depth);
    }
}

std::optional<Expr> Generator::read(Ty type, int depth, int max_length) {
    std::vector<const Place*> candidates;
    for (const auto& place : scope_->places) {
        // An element's indices are expressions too: only at depth > 0, so that they end.
        if (place.type == type && (type != Ty::String || place.capacity <= max_length) &&
            (depth > 0 || place.dims.empty())) {
            candidates.push_back(&place);
        }
    }
    if (candidates.empty()) {
        return std::nullopt;
    }
    return access(*one_of(candidates), depth, one_literal(type));
}

Expr Generator::access(const Place& place, int depth, std::string replacement) {
    if (place.dims.empty()) {
        return leaf(place.name, std::move(replacement));
    }
    // Indices reduced into the bounds: ((u MOD n) converted to DINT) + lower bound, u unsigned
    // of 32 or 64 bits so that its value is never negative.
    std::string text = place.name + "[";
    std::vector<Expr> indices;
    for (std::size_t d = 0; d < place.dims.size(); ++d) {
        const auto [lower, count] = place.dims[d];
        const Ty type = index_type();
        text += (d > 0 ? ", " : "") + type_name(type) + "_TO_DINT($" + std::to_string(d) + " MOD " +
                std::to_string(count) + ")" +
                (lower < 0 ? " - " + std::to_string(-lower) : " + " + std::to_string(lower));
        indices.push_back(expr(type, std::min(depth - 1, 1)));
    }
    return pattern(text + "]" + place.member, std::move(indices), std::move(replacement));
}

// Operands reduced with MOD k where k * k fits the type: no product or sum can overflow.
std::string reduction_modulus(Ty type) {
    switch (type) {
    case Ty::Sint:
        return "11";
    case Ty::Int:
        return "181";
    case Ty::Dint:
        return "46340";
    case Ty::Lint:
        return "3037000499";
    case Ty::Usint:
        return "15";
    default:
        return "255";
    }
}

Expr Generator::signed_expr(Ty type, int depth) {
    const std::string k = reduction_modulus(type);
    const std::string r = one_literal(type);
    auto sub = [&] {
        return expr(type, depth - 1);
    };
    switch (below(7)) {
    case 0:
    case 1: {
        const std::string op = std::array{" + ", " - ", " * "}[static_cast<std::size_t>(below(3))];
        return pattern("(($0 MOD " + k + ")" + op + "($1 MOD " + k + "))", {sub(), sub()}, r);
    }
    case 2:
        // A divisor of the form 4m + 2 is never 0 nor -1 (the one quotient that overflows).
        return pattern("($0 " + std::string(chance(50) ? "/" : "MOD") + " (($1 MOD " + k +
                           ") * 4 + 2))",
                       {sub(), sub()}, r);
    case 3:
        return pattern("(-($0 MOD " + k + "))", {sub()}, r);
    case 4:
        return pattern("ABS($0 MOD " + k + ")", {sub()}, r);
    case 5:
        if (type == Ty::Lint && options_.times && chance(50)) {
            // LTIME counts nanoseconds (st-language.md): a duration's, unrounded.
            return pattern("LTIME_TO_LINT(TIME_TO_LTIME($0))", {duration(depth - 1)}, r);
        }
        if (type == Ty::Int && options_.strings) {
            return chance(50)
                       ? pattern("LEN($0)", {string_expr(depth - 1, 80)}, r)
                       // FIND of an empty string is left open: IN2 is never empty.
                       : pattern("FIND($0, CONCAT($1, 'q'))",
                                 {string_expr(depth - 1, 40), string_expr(depth - 1, 39)}, r);
        }
        return conversion_to(type, depth);
    default:
        if (type == Ty::Dint && options_.reals) {
            return pattern("TRUNC(LIMIT(-1.0E9, $0, 1.0E9))", {expr(Ty::Lreal, depth - 1)}, r);
        }
        return conversion_to(type, depth);
    }
}

Expr Generator::duration(int depth) {
    const std::string r = "T#1ms";
    if (depth <= 0 || chance(25)) {
        return chance(50) ? leaf("T#" + std::to_string(below(200'000) - 100'000) + "ms", r)
                          : pattern("DINT_TO_TIME($0)", {expr(Ty::Dint, depth - 1)}, r);
    }
    auto sub = [&] {
        return duration(depth - 1);
    };
    // Integer factors, kept small, and divisors of the form 4m + 2 (never 0 nor -1).
    auto factor = [&] {
        return pattern("($0 MOD 1000)", {expr(Ty::Dint, depth - 1)}, "1");
    };
    auto sign = [&] {
        return std::string(chance(50) ? " + " : " - ");
    };
    // Points in time away from midnight and the epoch, moved and taken back to durations: a
    // time of day wraps around midnight (table 30).
    const std::string tod = "TOD#" + std::to_string(below(24)) + ":" + std::to_string(below(60)) +
                            ":" + std::to_string(below(60)) + "." + std::to_string(below(1000));
    const std::string dt = "DT#2024-01-31-12:00:00";
    switch (below(7)) {
    case 0:
        return pattern("($0" + sign() + "$1)", {sub(), sub()}, r);
    case 1:
        return pattern("($0 * $1)", {sub(), factor()}, r);
    case 2:
        return pattern("($0 / ($1 * 4 + 2))", {sub(), factor()}, r);
    case 3:
        return pattern("((" + tod + sign() + "$0) - TOD#00:00:00)", {sub()}, r);
    case 4:
        return pattern("((" + dt + sign() + "$0) - DT#2024-01-01-00:00:00)", {sub()}, r);
    case 5:
        // Table 22: a date is the day and a time of day the time since midnight of any time,
        // at either width.
        switch (below(4)) {
        case 0:
            return pattern("(TIME_TO_TOD($0) - TOD#00:00:00)", {sub()}, r);
        case 1:
            return pattern("(DT_TO_DATE(" + dt + sign() + "$0) - D#2024-01-01)", {sub()}, r);
        case 2:
            return pattern("LTIME_TO_TIME(LDT_TO_LTOD(DT_TO_LDT(" + dt + sign() +
                               "$0)) - LTOD#00:00:00)",
                           {sub()}, r);
        default:
            return pattern("TOD_TO_TIME(DT_TO_TOD(" + dt + sign() + "$0))", {sub()}, r);
        }
    default:
        // ADD and MUL are extensible, each step a row of table 30 (table 24).
        switch (below(3)) {
        case 0:
            return pattern("ADD($0, $1, $2)", {sub(), sub(), sub()}, r);
        case 1:
            return pattern("MUL($0, $1, $2)", {sub(), factor(), factor()}, r);
        default:
            return pattern("(ADD(" + tod + ", $0, $1) - TOD#00:00:00)", {sub(), sub()}, r);
        }
    }
}

Expr Generator::in_range(Ty type, Expr value) {
    // Half the time the result stays as computed in DINT (st-language.md), to be cut where it is
    // stored or passed to an input; otherwise it is cut here, explicitly.
    if (!is_narrow(type) || is_signed(type) || chance(50)) {
        return value;
    }
    const std::string wide = is_bit_string(type) ? "LWORD" : "DINT";
    return pattern(wide + "_TO_" + type_name(type) + "($0)", {std::move(value)}, one_literal(type));
}

Expr Generator::unsigned_expr(Ty type, int depth) {
    const std::string r = one_literal(type);
    auto sub = [&] {
        return expr(type, depth - 1);
    };
    // UDINT and ULINT wrap; USINT and UINT are computed in DINT and must stay small there.
    const bool wraps = !is_narrow(type);
    const std::string k = reduction_modulus(type);
    switch (below(4)) {
    case 0:
        return in_range(type, pattern(chance(50) ? "($0 + $1)" : "($0 - $1)", {sub(), sub()}, r));
    case 1:
        return wraps ? pattern("($0 * $1)", {sub(), sub()}, r)
                     : pattern("(($0 MOD " + k + ") * ($1 MOD " + k + "))", {sub(), sub()}, r);
    case 2:
        // An odd divisor is never 0, whatever the width it is computed in.
        return pattern("($0 " + std::string(chance(50) ? "/" : "MOD") + " (($1 MOD " + k +
                           ") * 2 + 1))",
                       {sub(), sub()}, r);
    default:
        return conversion_to(type, depth);
    }
}

Expr Generator::bit_string_expr(Ty type, int depth) {
    const std::string r = one_literal(type);
    auto sub = [&] {
        return expr(type, depth - 1);
    };
    const std::string n = std::to_string(below(bits_of(type)));
    switch (below(8)) {
    case 0:
    case 1: {
        const std::string op =
            std::array{" AND ", " OR ", " XOR "}[static_cast<std::size_t>(below(3))];
        return pattern("($0" + op + "$1)", {sub(), sub()}, r);
    }
    case 2:
        return in_range(type, pattern("(NOT $0)", {sub()}, r));
    case 3:
    case 4: {
        const std::string shift =
            std::array{"SHL", "SHR", "ROL", "ROR"}[static_cast<std::size_t>(below(4))];
        return in_range(type, pattern(shift + "($0, " + n + ")", {sub()}, r));
    }
    case 5:
        return in_range(type, pattern(chance(50) ? "($0 + $1)" : "($0 - $1)", {sub(), sub()}, r));
    case 6:
        // BYTE and WORD may be computed in DINT: factors below 256 cannot overflow it.
        return is_narrow(type)
                   ? in_range(type, pattern("(($0 AND 16#FF) * ($1 AND 16#FF))", {sub(), sub()}, r))
                   : pattern("($0 * $1)", {sub(), sub()}, r);
    default:
        return pattern("($0 " + std::string(chance(50) ? "/" : "MOD") + " ($1 OR 1))",
                       {sub(), sub()}, r);
    }
}

Expr Generator::bool_expr(int depth) {
    const std::string r = one_literal(Ty::Bool);
    switch (below(5)) {
    case 0:
    case 1: {
        // Strings compared in arguments next to others are how issue 16 item 2 showed.
        const Ty type = options_.strings && chance(25) ? Ty::String : any_scalar_type();
        const std::string op = std::array{
            " = ", " <> ", " < ", " <= ", " > ", " >= "}[static_cast<std::size_t>(below(6))];
        // A variable of a small integer type negated: computed in DINT, so -(-32768) > 0 and
        // -(USINT 5) < 0 (docs/st-language.md). A variable, not an expression, so that no
        // constant wraps.
        if ((is_signed(type) || is_unsigned(type)) && bits_of(type) < 32 && chance(25)) {
            if (auto negated = read(type, 0, 40)) {
                return pattern("(-$0" + op + "$1)",
                               {std::move(*negated), expr(type, depth - 1, 40)}, r);
            }
        }
        return pattern("($0" + op + "$1)", {expr(type, depth - 1, 40), expr(type, depth - 1, 40)},
                       r);
    }
    case 2: {
        const std::string op =
            std::array{" AND ", " OR ", " XOR "}[static_cast<std::size_t>(below(3))];
        return pattern("($0" + op + "$1)", {expr(Ty::Bool, depth - 1), expr(Ty::Bool, depth - 1)},
                       r);
    }
    case 3:
        return pattern("(NOT $0)", {expr(Ty::Bool, depth - 1)}, r);
    default: {
        // A bit of a bit string variable.
        std::vector<const Place*> words;
        for (const auto& place : scope_->places) {
            if (is_bit_string(place.type) && place.dims.empty()) {
                words.push_back(&place);
            }
        }
        if (words.empty()) {
            return conversion_to(Ty::Bool, depth);
        }
        const Place& word = *one_of(words);
        return leaf(word.name + "." + std::to_string(below(bits_of(word.type))), r);
    }
    }
}

Expr Generator::real_expr(Ty type, int depth) {
    const std::string r = one_literal(type);
    auto sub = [&] {
        return expr(type, depth - 1);
    };
    // Sums and quotients of bounded values stay bounded; factors are clamped first.
    switch (below(6)) {
    case 0:
    case 1:
        return pattern(chance(50) ? "($0 + $1)" : "($0 - $1)", {sub(), sub()}, r);
    case 2:
        return pattern("(LIMIT(-1.0E6, $0, 1.0E6) * LIMIT(-1.0E6, $1, 1.0E6))", {sub(), sub()}, r);
    case 3:
        return pattern("($0 / (ABS($1) + 1.0))", {sub(), sub()}, r);
    case 4:
        return pattern(chance(50) ? "SQRT(ABS($0))" : "ABS($0)", {sub()}, r);
    default:
        return type == Ty::Real ? pattern("LREAL_TO_REAL($0)", {expr(Ty::Lreal, depth - 1)}, r)
                                : pattern("REAL_TO_LREAL($0)", {expr(Ty::Real, depth - 1)}, r);
    }
}

Expr Generator::string_expr(int depth, int max_length) {
    const std::string r = one_literal(Ty::String);
    if (depth <= 0 || max_length < 2) {
        return leaf(string_literal(max_length), r);
    }
    const std::string l = std::to_string(below(5));
    const std::string p = std::to_string(1 + below(5));
    // Positions inside a non-empty string: IN is extended by one character, P is at most its
    // length and L at most what is left from P.
    const std::string in = "CONCAT($0, '" + std::string(1, kAlphabet[below(26)]) + "')";
    const std::string position = "MIN(" + p + ", LEN(" + in + "))";
    const std::string length = "MIN(" + l + ", LEN(" + in + ") + 1 - " + position + ")";
    const int half = max_length / 2;
    switch (below(8)) {
    case 0:
        return pattern("CONCAT($0, $1)",
                       {string_expr(depth - 1, half), expr(Ty::String, depth - 1, half)}, r);
    case 1:
        return pattern(std::string(chance(50) ? "LEFT" : "RIGHT") + "($0, MIN(" + l + ", LEN($0)))",
                       {expr(Ty::String, depth - 1, max_length)}, r);
    case 2:
        return pattern("MID(" + in + ", " + length + ", " + position + ")",
                       {expr(Ty::String, depth - 1, max_length - 1)}, r);
    case 3:
        return pattern("DELETE(" + in + ", " + length + ", " + position + ")",
                       {expr(Ty::String, depth - 1, max_length - 1)}, r);
    case 4:
        return pattern("REPLACE(" + in + ", $1, " + length + ", " + position + ")",
                       {expr(Ty::String, depth - 1, half - 1), expr(Ty::String, depth - 1, half)},
                       r);
    case 5:
        return pattern("INSERT($0, $1, MIN(" + l + ", LEN($0)))",
                       {expr(Ty::String, depth - 1, half), expr(Ty::String, depth - 1, half)}, r);
    default:
        return leaf(string_literal(max_length), r);
    }
}

std::optional<Expr> Generator::selection(Ty type, int depth, int max_length) {
    const std::string r = one_literal(type);
    auto sub = [&] {
        return expr(type, depth - 1, max_length);
    };
    const bool ordered = type != Ty::Bool && (type != Ty::String || options_.string_max_min_limit);
    switch (below(ordered ? 5 : 2)) {
    case 0:
        return pattern("SEL($0, $1, $2)", {expr(Ty::Bool, depth - 1), sub(), sub()}, r);
    case 1:
        return pattern("MUX($0 MOD 3, $1, $2, $3)",
                       {expr(index_type(), depth - 1), sub(), sub(), sub()}, r);
    case 2:
        return pattern("MAX($0, $1)", {sub(), sub()}, r);
    case 3:
        return pattern("MIN($0, $1)", {sub(), sub()}, r);
    default: {
        // Bounds in order: LIMIT of crossed bounds is left to the implementation.
        std::string low = literal(type, std::min(max_length, 6));
        std::string high = literal(type, std::min(max_length, 6));
        if (is_integer(type) || is_real(type)) {
            return pattern("LIMIT(MIN($1, $2), $0, MAX($1, $2))",
                           {sub(), leaf(low, r), leaf(high, r)}, r);
        }
        if (high < low) {
            std::swap(low, high);
        }
        return pattern("LIMIT(" + low + ", $0, " + high + ")", {sub()}, r);
    }
    }
}

std::optional<Expr> Generator::call(Ty type, int depth, int max_length) {
    std::vector<const Function*> candidates;
    for (const auto& function : functions_) {
        if (function.result == type && !function.in_out &&
            (type != Ty::String || function.capacity <= max_length)) {
            candidates.push_back(&function);
        }
    }
    if (candidates.empty()) {
        return std::nullopt;
    }
    return arguments_call(*one_of(candidates), depth);
}

Expr Generator::arguments_call(const Function& function, int depth) {
    std::string text = function.name + "(";
    std::vector<Expr> arguments;
    const bool formal = chance(30);
    for (std::size_t i = 0; i < function.inputs.size(); ++i) {
        const Param& input = function.inputs[i];
        text += (i > 0 ? ", " : "") + (formal ? input.name + " := " : std::string()) + "$" +
                std::to_string(i);
        arguments.push_back(expr(input.type, depth - 1, input.capacity));
    }
    return pattern(text + ")", std::move(arguments), one_literal(function.result));
}

Expr Generator::conversion_to(Ty type, int depth) {
    if (is_integer(type) && options_.reals && chance(15)) {
        return real_to_integer(type, depth);
    }
    Ty from = type;
    while (from == type || from == Ty::String || (is_real(from) && is_integer(type))) {
        from = chance(10) ? Ty::Bool : any_scalar_type();
    }
    if ((type == Ty::Bool && is_real(from)) || (from == Ty::Bool && is_real(type))) {
        // IEC 61131-3 converts BOOL to and from integers and bit strings only.
        from = any_integer_type();
    }
    // Chains through a second conversion reach the 32/64-bit cases of issue 16 item 1.
    Expr inner =
        chance(30) && is_integer(from) ? conversion_to(from, depth - 1) : expr(from, depth - 1);
    return pattern(type_name(from) + "_TO_" + type_name(type) + "($0)", {std::move(inner)},
                   one_literal(type));
}

Expr Generator::real_to_integer(Ty type, int depth) {
    const Ty from = chance(50) ? Ty::Real : Ty::Lreal;
    const std::string low = is_signed(type) ? min_text(type) : "0";
    std::string high = max_text(type);
    if (bits_of(type) >= 32) {
        // REAL holds integers exactly up to 2^24: bounds it represents exactly.
        high = is_signed(type) ? "1.0E6" : "2.0E6";
    }
    const std::string lo = bits_of(type) >= 32 && is_signed(type) ? "-1.0E6" : low + ".0";
    const std::string hi = high.find('E') != std::string::npos ? high : high + ".0";
    const std::string convert = type_name(from) + "_TO_" + type_name(type);
    if (options_.real_ties) {
        return pattern(convert + "(LIMIT(" + lo + ", $0, " + hi + "))", {expr(from, depth - 1)},
                       one_literal(type));
    }
    // An integer plus a fraction other than one half: never a tie, whatever the operand.
    const std::string fraction =
        std::array{"0.25", "0.375", "0.75", "-0.25"}[static_cast<std::size_t>(below(4))];
    return pattern(convert + "(LIMIT(" + lo + ", DINT_TO_" + type_name(from) +
                       "(TRUNC(LIMIT(-1.0E6, $0, 1.0E6))) + " + fraction + ", " + hi + "))",
                   {expr(from, depth - 1)}, one_literal(type));
}

Expr Generator::constant_expr(Ty type, int depth) {
    const std::string r = one_literal(type);
    // What the compiler folds in an initial value (types/initial_constant.cpp): arithmetic on
    // integers below 2^63 and on reals; NOT, AND, OR and XOR on BOOLs and integers.
    const bool arithmetic =
        is_real(type) || is_signed(type) || (is_unsigned(type) && type != Ty::Ulint);
    const bool logic = type == Ty::Bool || is_integer(type);
    if ((!arithmetic && !logic) || depth <= 0 || chance(25)) {
        std::vector<const Place*> constants;
        for (const auto& place : scope_->places) {
            if (place.type == type) {
                constants.push_back(&place);
            }
        }
        return !constants.empty() && chance(50) ? leaf(one_of(constants)->name, r)
                                                : leaf(literal(type), r);
    }
    auto sub = [&] {
        return constant_expr(type, depth - 1);
    };
    if (logic && (!arithmetic || chance(40))) {
        // NOT flips the bits of the type (a BYTE's eight), which keeps every value in it.
        switch (below(4)) {
        case 0:
            return pattern("(NOT $0)", {sub()}, r);
        case 1:
            return pattern("($0 AND $1)", {sub(), sub()}, r);
        case 2:
            return pattern("($0 OR $1)", {sub(), sub()}, r);
        default:
            return pattern("($0 XOR $1)", {sub(), sub()}, r);
        }
    }
    if (is_real(type)) {
        // Literals are eighths below 125 000 and products take only literals and names: far
        // from infinity, and sums of products round twice in REAL.
        switch (below(depth > 1 ? 3 : 4)) {
        case 0:
        case 1:
            return pattern(chance(50) ? "($0 + $1)" : "($0 - $1)", {sub(), sub()}, r);
        case 2:
            return pattern("($0 / " + type_name(type) + "#2.5)", {sub()}, r);
        default:
            return pattern("($0 * $1)", {sub(), sub()}, r);
        }
    }
    // Integers reduced as in signed_expr and unsigned_expr, so that no value leaves its type
    // (the compiler refuses a constant that does not fit); divisors are never 0 nor -1.
    const std::string k = reduction_modulus(type);
    switch (below(4)) {
    case 0:
        return pattern("(($0 MOD " + k + ") * ($1 MOD " + k + "))", {sub(), sub()}, r);
    case 1:
        return pattern("(($0 MOD " + k + ")" + (is_signed(type) ? " - " : " + ") + "($1 MOD " + k +
                           "))",
                       {sub(), sub()}, r);
    case 2:
        return pattern("($0 " + std::string(chance(50) ? "/" : "MOD") + " (($1 MOD " + k + ") * " +
                           (is_signed(type) ? "4 + 2))" : "2 + 1))"),
                       {sub(), sub()}, r);
    default:
        return is_signed(type) ? pattern("(-($0 MOD " + k + "))", {sub()}, r) : sub();
    }
}

// ---------------------------------------------------------------- statements

Block Generator::statements(Scope& scope, int count, int depth) {
    Block block;
    for (int i = 0; i < count; ++i) {
        one_statement(scope, depth, block);
    }
    return block;
}

void Generator::one_statement(Scope& scope, int depth, Block& out) {
    const int kind = below(depth > 0 ? 20 : 10);
    if (kind < 10) {
        assignment(scope, out);
    } else if (kind < 12) {
        if_statement(scope, depth, out);
    } else if (kind < 13 && options_.case_statements) {
        case_statement(scope, depth, out);
    } else if (kind < 14 && options_.loops) {
        for_statement(scope, depth, out);
    } else if (kind < 15 && options_.loops) {
        while_statement(scope, depth, out, chance(50));
    } else if (kind < 16 && scope.loops > 0) {
        loop_exit(out);
    } else if (kind < 18 && !scope.fb_instances.empty()) {
        fb_call(scope, out);
    } else if (kind < 19 && options_.in_out) {
        in_out_call(scope, out);
    } else {
        assignment(scope, out);
    }
}

void Generator::assignment(Scope& scope, Block& out) {
    std::vector<const Place*> targets;
    for (const auto& place : scope.places) {
        if (place.writable) {
            targets.push_back(&place);
        }
    }
    if (targets.empty()) {
        return;
    }
    const Place& target = *one_of(targets);
    Expr value = expr(target.type, options_.expression_depth);
    if (is_real(target.type)) {
        // Stored reals stay far from the largest REAL, however often loops add them up.
        value = pattern("LIMIT(-1.0E20, $0, 1.0E20)", {std::move(value)}, one_literal(target.type));
    }
    Expr lhs = access(target, 1, {});
    Expr folded = lhs;
    folded.replacement = one_literal(target.type);
    out.push_back(statement("$e := $e;", {std::move(lhs), std::move(value)}));
    fold(scope, folded, target.type, out);
}

void Generator::fold(const Scope& scope, const Expr& value, Ty type, Block& out) {
    if (!scope.main) {
        return;
    }
    std::string text;
    switch (type) {
    case Ty::Bool:
        text = "Mix(checksum, BOOL_TO_ULINT($0))";
        break;
    case Ty::Real:
        text = "MixR(checksum, REAL_TO_LREAL($0))";
        break;
    case Ty::Lreal:
        text = "MixR(checksum, $0)";
        break;
    case Ty::String:
        text = "MixS(checksum, $0)";
        break;
    case Ty::Ulint:
        text = "Mix(checksum, $0)";
        break;
    case Ty::Lint:
        text = "Mix(checksum, LINT_TO_ULINT($0))";
        break;
    default:
        text = is_signed(type) ? "Mix(checksum, LINT_TO_ULINT(" + type_name(type) + "_TO_LINT($0)))"
                               : "Mix(checksum, " + type_name(type) + "_TO_ULINT($0))";
    }
    out.push_back(statement("checksum := $e;", {pattern(text, {value}, "")}));
}

void Generator::if_statement(Scope& scope, int depth, Block& out) {
    const int depth_inside = depth - 1;
    Expr condition = expr(Ty::Bool, options_.expression_depth);
    Block then_block = statements(scope, 1 + below(3), depth_inside);
    if (chance(30)) {
        Expr second = expr(Ty::Bool, options_.expression_depth - 1);
        Block elsif_block = statements(scope, 1 + below(2), depth_inside);
        Block else_block = statements(scope, 1 + below(2), depth_inside);
        out.push_back(statement(
            "IF $e THEN$bELSIF $e THEN$bELSE$bEND_IF;", {std::move(condition), std::move(second)},
            {std::move(then_block), std::move(elsif_block), std::move(else_block)}));
        return;
    }
    if (chance(50)) {
        Block else_block = statements(scope, 1 + below(2), depth_inside);
        out.push_back(statement("IF $e THEN$bELSE$bEND_IF;", {std::move(condition)},
                                {std::move(then_block), std::move(else_block)}));
        return;
    }
    out.push_back(
        statement("IF $e THEN$bEND_IF;", {std::move(condition)}, {std::move(then_block)}));
}

void Generator::case_statement(Scope& scope, int depth, Block& out) {
    Ty type = any_integer_type();
    std::vector<std::string> labels;
    Expr selector;
    if (options_.huge_case_labels && chance(25)) {
        // Labels above 2^63 - 1 on a ULINT selector (issue 16 item 11).
        type = Ty::Ulint;
        const std::uint64_t base = (1ULL << 63) + (random_() >> 2);
        selector = pattern("(ULINT#" + std::to_string(base) + " + ($0 MOD 4))",
                           {expr(Ty::Ulint, options_.expression_depth - 1)}, "");
        for (std::uint64_t i = 0; i < 3; ++i) {
            labels.push_back((chance(50) ? "ULINT#" : "") + std::to_string(base + i));
        }
    } else {
        const int modulus = is_signed(type) ? 4 : 6;
        selector = pattern("($0 MOD " + std::to_string(modulus) + ")",
                           {expr(type, options_.expression_depth - 1)}, one_literal(type));
        std::set<int> values;
        while (values.size() < 3) {
            values.insert(below(2 * modulus - 1) - (is_signed(type) ? modulus - 1 : 0));
        }
        for (const int value : values) {
            labels.push_back(std::to_string(value));
        }
        if (chance(40) && !is_signed(type) && *values.rbegin() < 4) {
            labels.push_back(std::to_string(*values.rbegin() + 1) + ".." +
                             std::to_string(*values.rbegin() + 2));
        }
    }
    std::string text = "CASE $e OF";
    std::vector<Block> blocks;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        // Two labels share an arm now and then: a list of labels.
        std::string arm = labels[i];
        if (i + 1 < labels.size() && chance(25)) {
            arm += ", " + labels[++i];
        }
        text += "$b";
        blocks.push_back(
            Block{statement(arm + ":$b", {}, {statements(scope, 1 + below(2), depth - 1)})});
    }
    if (chance(60)) {
        text += "$b";
        blocks.push_back(
            Block{statement("ELSE$b", {}, {statements(scope, 1 + below(2), depth - 1)})});
    }
    out.push_back(statement(text + "END_CASE;", {std::move(selector)}, std::move(blocks)));
}

std::string Generator::counter(Scope& scope) {
    return "c" + std::to_string(scope.counters++);
}

void Generator::for_statement(Scope& scope, int depth, Block& out) {
    const std::string name = counter(scope);
    const int from = below(4) - 1;
    const bool down = chance(20);
    // Now and then at the end of DINT, where a step past it wraps around and ends the loop.
    const std::int64_t offset = !chance(15) ? 0 : down ? -2147483644 : 2147483643;
    std::string head = "FOR " + name + " := ";
    Expr limit = pattern(offset == 0 ? "($0 MOD 5)" : "(" + std::to_string(offset) + " + $0 MOD 5)",
                         {expr(Ty::Dint, 1)}, "DINT#1");
    if (down) {
        head += std::to_string(offset + from + 3) + " TO $e BY -" + std::to_string(1 + below(2));
    } else {
        head += std::to_string(offset + from) + " TO $e" + (chance(30) ? " BY 2" : "");
    }
    ++scope.loops;
    scope.places.push_back(scalar(name, Ty::Dint, 0, false));
    Block body = statements(scope, 1 + below(3), depth - 1);
    scope.places.pop_back();
    --scope.loops;
    out.push_back(statement(head + " DO$bEND_FOR;", {std::move(limit)}, {std::move(body)}));
}

void Generator::while_statement(Scope& scope, int depth, Block& out, bool repeat) {
    const std::string name = counter(scope);
    const std::string count = std::to_string(1 + below(4));
    out.push_back(statement(name + " := 0;"));
    ++scope.loops;
    Block body;
    // The counter's increment comes first so that CONTINUE cannot skip it.
    body.push_back(statement(name + " := " + name + " + 1;", {}, {}, false));
    Block rest = statements(scope, 1 + below(3), depth - 1);
    body.insert(body.end(), std::make_move_iterator(rest.begin()),
                std::make_move_iterator(rest.end()));
    --scope.loops;
    if (repeat) {
        out.push_back(statement("REPEAT$bUNTIL " + name + " >= " + count + " OR $e END_REPEAT;",
                                {expr(Ty::Bool, 1)}, {std::move(body)}));
    } else {
        out.push_back(
            statement("WHILE " + name + " < " + count + " DO$bEND_WHILE;", {}, {std::move(body)}));
    }
    scope.places.push_back(scalar(name, Ty::Dint, 0, false));
}

void Generator::loop_exit(Block& out) {
    out.push_back(
        statement(std::string("IF $e THEN ") + (chance(50) ? "EXIT" : "CONTINUE") + "; END_IF;",
                  {expr(Ty::Bool, 1)}));
}

void Generator::fb_call(Scope& scope, Block& out) {
    const std::size_t which =
        static_cast<std::size_t>(below(static_cast<int>(scope.fb_instances.size())));
    const FunctionBlock& block = blocks_[scope.fb_types[which]];
    const std::string& instance = scope.fb_instances[which];
    std::string text = instance + "(";
    std::vector<Expr> arguments;
    for (std::size_t i = 0; i < block.inputs.size(); ++i) {
        const Param& input = block.inputs[i];
        text += (i > 0 ? ", " : "") + input.name + " := $" + std::to_string(i);
        arguments.push_back(expr(input.type, options_.expression_depth - 1, input.capacity));
    }
    out.push_back(statement("$e;", {pattern(text + ")", std::move(arguments), "")}));
    for (const Param& output : block.outputs) {
        fold(scope, leaf(instance + "." + output.name, one_literal(output.type)), output.type, out);
    }
}

void Generator::in_out_call(Scope& scope, Block& out) {
    std::vector<const Function*> candidates;
    for (const auto& function : functions_) {
        if (function.in_out) {
            candidates.push_back(&function);
        }
    }
    if (candidates.empty()) {
        return assignment(scope, out);
    }
    const Function& function = *one_of(candidates);
    std::vector<const Place*> variables;
    std::vector<const Place*> results;
    for (const auto& place : scope.places) {
        if (place.writable && place.dims.empty() && place.type == function.in_out->type &&
            place.capacity == function.in_out->capacity) {
            variables.push_back(&place);
        }
        if (place.writable && place.type == function.result && place.dims.empty()) {
            results.push_back(&place);
        }
    }
    if (variables.empty() || results.empty()) {
        return assignment(scope, out);
    }
    const Place& variable = *one_of(variables);
    const Place& result = *one_of(results);
    Expr call_expr = arguments_call(function, options_.expression_depth);
    // Formal arguments: the VAR_IN_OUT joins them by name.
    std::string text = function.name + "(";
    for (std::size_t i = 0; i < function.inputs.size(); ++i) {
        text += function.inputs[i].name + " := $" + std::to_string(i) + ", ";
    }
    text += function.in_out->name + " := " + variable.name + ")";
    Expr with_in_out = pattern(text, std::move(call_expr.operands), "");
    out.push_back(statement(result.name + " := $e;", {std::move(with_in_out)}));
    fold(scope, leaf(result.name, one_literal(result.type)), result.type, out);
    fold(scope, leaf(variable.name, one_literal(variable.type)), variable.type, out);
}

// ---------------------------------------------------------------- declarations

Stmt Generator::declaration(const std::string& name, const std::string& type_text,
                            const std::string& initial) {
    return statement(name + " : " + type_text + (initial.empty() ? "" : " := " + initial) + ";");
}

std::string Generator::declare_type(Ty type, int capacity) {
    return type == Ty::String ? "STRING[" + std::to_string(capacity) + "]" : type_name(type);
}

std::vector<Place> Generator::declare_variables(const std::string& prefix, int count, Block& decls,
                                                bool initialise) {
    std::vector<Place> places;
    for (int i = 0; i < count; ++i) {
        Place place;
        place.name = prefix + std::to_string(names_++);
        place.type = any_scalar_type();
        place.capacity = place.type == Ty::String ? string_capacity() : 0;
        const int shape = below(10);
        std::string type_text = declare_type(place.type, place.capacity);
        if (options_.arrays && shape < 2) {
            place.dims.push_back({below(3) == 0 ? -2 : below(3), 2 + below(4)});
            if (shape == 1) {
                place.dims.push_back({1, 2 + below(2)});
            }
            std::string bounds;
            for (const auto& [lower, n] : place.dims) {
                bounds += (bounds.empty() ? "" : ", ") + std::to_string(lower) + ".." +
                          std::to_string(lower + n - 1);
            }
            type_text = "ARRAY[" + bounds + "] OF " + type_text;
            decls.push_back(declaration(place.name, type_text, ""));
        } else if (options_.structs && shape == 2 && !structs_.empty()) {
            const auto& type =
                structs_[static_cast<std::size_t>(below(static_cast<int>(structs_.size())))];
            const bool array = options_.arrays && chance(40);
            decls.push_back(
                declaration(place.name, array ? "ARRAY[0..2] OF " + type.name : type.name, ""));
            for (const Param& member : type.members) {
                Place field = scalar(array ? place.name : place.name + "." + member.name,
                                     member.type, member.capacity, true);
                field.member = array ? "." + member.name : std::string();
                if (array) {
                    field.dims.push_back({0, 3});
                }
                places.push_back(field);
            }
            continue;
        } else {
            decls.push_back(
                declaration(place.name, type_text,
                            initialise && chance(70) ? literal(place.type, place.capacity) : ""));
        }
        places.push_back(place);
    }
    return places;
}

void Generator::struct_types(Block& program) {
    if (!options_.structs) {
        return;
    }
    for (int s = 0; s < 1 + below(2); ++s) {
        StructType type{"S" + std::to_string(s), {}};
        Block members;
        for (int m = 0; m < 2 + below(3); ++m) {
            Param member{"m" + std::to_string(m), any_scalar_type(), 0};
            member.capacity = member.type == Ty::String ? string_capacity() : 0;
            members.push_back(declaration(member.name,
                                          member.type == Ty::String
                                              ? "STRING[" + std::to_string(member.capacity) + "]"
                                              : type_name(member.type),
                                          ""));
            type.members.push_back(member);
        }
        program.push_back(statement("TYPE " + type.name + " : STRUCT$bEND_STRUCT; END_TYPE", {},
                                    {std::move(members)}));
        structs_.push_back(std::move(type));
    }
}

void Generator::function(Block& program) {
    Function function;
    function.name = "F" + std::to_string(functions_.size());
    function.result = any_scalar_type();
    function.capacity = function.result == Ty::String ? string_capacity() : 80;
    Scope scope;
    scope_ = &scope;
    Block inputs;
    const int count = 2 + below(std::max(1, options_.max_inputs - 1));
    for (int i = 0; i < count; ++i) {
        Param input{"p" + std::to_string(i), any_scalar_type(), 0};
        if (input.type == Ty::String) {
            input.capacity = chance(30) ? 80 : string_capacity();
        }
        inputs.push_back(declaration(input.name,
                                     input.type == Ty::String && input.capacity == 80
                                         ? "STRING"
                                         : declare_type(input.type, input.capacity),
                                     ""));
        scope.places.push_back(scalar(input.name, input.type, input.capacity, false));
        function.inputs.push_back(input);
    }
    Block in_out;
    if (options_.in_out && chance(30)) {
        Param io{"io", any_scalar_type(), 0};
        io.capacity = io.type == Ty::String ? string_capacity() : 0;
        in_out.push_back(declaration(io.name, declare_type(io.type, io.capacity), ""));
        scope.places.push_back(scalar(io.name, io.type, io.capacity, true));
        function.in_out = io;
    }
    Block locals;
    auto local_places = declare_variables("t", 1 + below(3), locals, true);
    scope.places.insert(scope.places.end(), local_places.begin(), local_places.end());
    Block body = statements(scope, 1 + below(4), 1);
    Expr result = expr(function.result, options_.expression_depth, function.capacity);
    if (is_real(function.result)) {
        result = pattern("LIMIT(-1.0E20, $0, 1.0E20)", {std::move(result)},
                         one_literal(function.result));
    }
    body.push_back(statement(function.name + " := $e;", {std::move(result)}, {}, false));
    for (int c = 0; c < scope.counters; ++c) {
        locals.push_back(declaration("c" + std::to_string(c), "DINT", ""));
    }
    const std::string result_type = function.result == Ty::String
                                        ? "STRING[" + std::to_string(function.capacity) + "]"
                                        : type_name(function.result);
    std::string text = "FUNCTION " + function.name + " : " + result_type + "\nVAR_INPUT$bEND_VAR\n";
    std::vector<Block> blocks{std::move(inputs)};
    if (function.in_out) {
        text += "VAR_IN_OUT$bEND_VAR\n";
        blocks.push_back(std::move(in_out));
    }
    text += "VAR$bEND_VAR\n$bEND_FUNCTION";
    blocks.push_back(std::move(locals));
    blocks.push_back(std::move(body));
    program.push_back(statement(text, {}, std::move(blocks)));
    functions_.push_back(std::move(function));
}

void Generator::function_block(Block& program) {
    FunctionBlock block;
    block.name = "B" + std::to_string(blocks_.size());
    Scope scope;
    scope_ = &scope;
    Block inputs;
    Block outputs;
    for (int i = 0; i < 1 + below(3); ++i) {
        Param input{"in" + std::to_string(i), any_scalar_type(), 0};
        input.capacity = input.type == Ty::String ? string_capacity() : 0;
        inputs.push_back(declaration(input.name, declare_type(input.type, input.capacity), ""));
        scope.places.push_back(scalar(input.name, input.type, input.capacity, false));
        block.inputs.push_back(input);
    }
    for (int i = 0; i < 1 + below(3); ++i) {
        Param output{"q" + std::to_string(i), any_scalar_type(), 0};
        output.capacity = output.type == Ty::String ? string_capacity() : 0;
        outputs.push_back(declaration(output.name, declare_type(output.type, output.capacity), ""));
        scope.places.push_back(scalar(output.name, output.type, output.capacity, true));
        block.outputs.push_back(output);
    }
    // State that lives from one call, and one scan, to the next.
    Block state;
    auto state_places = declare_variables("s", 1 + below(3), state, true);
    scope.places.insert(scope.places.end(), state_places.begin(), state_places.end());
    Block body = statements(scope, 2 + below(4), 2);
    for (int c = 0; c < scope.counters; ++c) {
        state.push_back(declaration("c" + std::to_string(c), "DINT", ""));
    }
    program.push_back(statement(
        "FUNCTION_BLOCK " + block.name +
            "\nVAR_INPUT$bEND_VAR\nVAR_OUTPUT$bEND_VAR\nVAR$bEND_VAR\n$bEND_FUNCTION_BLOCK",
        {}, {std::move(inputs), std::move(outputs), std::move(state), std::move(body)}));
    blocks_.push_back(std::move(block));
}

void Generator::final_folds(Scope& scope, Block& body) {
    // Everything Main holds goes into the checksum once more at the end of each scan.
    for (const Place& place : scope.places) {
        if (!place.writable) {
            continue;
        }
        if (place.dims.empty()) {
            fold(scope, leaf(place.name, one_literal(place.type)), place.type, body);
            continue;
        }
        // An array: one FOR loop per dimension around the fold of an element.
        std::vector<std::string> counters;
        std::string element = place.name + "[";
        for (std::size_t d = 0; d < place.dims.size(); ++d) {
            counters.push_back(counter(scope));
            element += (d > 0 ? ", " : "") + counters.back();
        }
        Block loops;
        fold(scope, leaf(element + "]" + place.member, one_literal(place.type)), place.type, loops);
        for (std::size_t d = place.dims.size(); d-- > 0;) {
            const auto [lower, count] = place.dims[d];
            Block outer{statement("FOR " + counters[d] + " := " + std::to_string(lower) + " TO " +
                                      std::to_string(lower + count - 1) + " DO$bEND_FOR;",
                                  {}, {std::move(loops)})};
            loops = std::move(outer);
        }
        body.insert(body.end(), loops.begin(), loops.end());
    }
}

std::vector<Place> Generator::declare_constants(Block& decls) {
    std::vector<Place> constants;
    if (!options_.constants) {
        return constants;
    }
    for (int i = 0; i < 2 + below(4); ++i) {
        Ty type = any_scalar_type();
        while (type == Ty::String) {
            type = any_scalar_type();
        }
        Place place = scalar("k" + std::to_string(names_++), type, 0, false);
        const Expr value = constant_expr(type, 2);
        decls.push_back(declaration(place.name, type_name(type), render(value)));
        constants.push_back(place);
        scope_->places.push_back(place); // the next constants may name it
    }
    return constants;
}

void Generator::main_program(Block& program) {
    Scope scope;
    scope.main = true;
    scope_ = &scope;
    Block decls;
    decls.push_back(statement("checksum : ULINT;", {}, {}, false));
    auto places = declare_variables("v", 6 + below(6), decls, true);
    Block constant_decls;
    const std::vector<Place> constants = declare_constants(constant_decls);
    scope.places = places;
    scope.places.insert(scope.places.end(), constants.begin(), constants.end());
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        for (int n = 0; n < 1 + below(2); ++n) {
            const std::string instance = "fb" + std::to_string(names_++);
            decls.push_back(declaration(instance, blocks_[b].name, ""));
            scope.fb_instances.push_back(instance);
            scope.fb_types.push_back(b);
            for (const Param& output : blocks_[b].outputs) {
                scope.places.push_back(
                    scalar(instance + "." + output.name, output.type, output.capacity, false));
            }
        }
    }
    Block body;
    for (const Place& constant : constants) {
        fold(scope, leaf(constant.name, one_literal(constant.type)), constant.type, body);
    }
    Block statements_of_main = statements(scope, options_.statements, 2);
    body.insert(body.end(), statements_of_main.begin(), statements_of_main.end());
    // Every instance runs in every scan at least once, so that its state moves on.
    for (std::size_t i = 0; i < scope.fb_instances.size(); ++i) {
        Scope one = scope;
        one.fb_instances = {scope.fb_instances[i]};
        one.fb_types = {scope.fb_types[i]};
        fb_call(one, body);
    }
    final_folds(scope, body);
    for (int c = 0; c < scope.counters; ++c) {
        decls.push_back(declaration("c" + std::to_string(c), "DINT", ""));
    }
    if (constants.empty()) {
        program.push_back(statement("PROGRAM Main\nVAR$bEND_VAR\n$bEND_PROGRAM", {},
                                    {std::move(decls), std::move(body)}, false));
        return;
    }
    program.push_back(statement("PROGRAM Main\nVAR CONSTANT$bEND_VAR\nVAR$bEND_VAR\n$bEND_PROGRAM",
                                {}, {std::move(constant_decls), std::move(decls), std::move(body)},
                                false));
}

GeneratedProgram Generator::run() {
    GeneratedProgram result;
    for (const auto& text : checksum_functions()) {
        result.block.push_back(statement(text));
    }
    struct_types(result.block);
    for (int f = 0; f < options_.functions; ++f) {
        function(result.block);
    }
    for (int b = 0; b < options_.function_blocks; ++b) {
        function_block(result.block);
    }
    main_program(result.block);
    scope_ = nullptr;
    return result;
}

} // namespace

GeneratedProgram generate_program(std::mt19937_64& random, const GeneratorOptions& options) {
    return Generator(random, options).run();
}

} // namespace eposp::differential
