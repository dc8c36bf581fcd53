#pragma once

#include "eposp/compiler/ast/elementary_type.hpp"
#include "eposp/compiler/ast/identifier.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <variant>

namespace eposp::compiler::ast {

// Literal values are decoded exactly when the AST is built; `type` holds the prefix of a typed
// literal (`INT#16#FF`), empty when the type comes from the context.

/// Magnitude and sign rather than one signed type, so that both -2^63 (LINT) and 2^64-1 (ULINT)
/// are representable.
struct IntegerLiteral {
    std::uint64_t magnitude = 0;
    bool negative = false;
    std::optional<ElementaryType> type;
};

struct RealLiteral {
    double value = 0.0;
    std::optional<ElementaryType> type;
};

struct BoolLiteral {
    bool value = false;
};

/// TIME / LTIME: a signed duration in nanoseconds.
struct DurationLiteral {
    std::int64_t nanoseconds = 0;
    ElementaryType type = ElementaryType::Time;
};

/// DATE, TIME_OF_DAY, DATE_AND_TIME and their long forms, as nanoseconds since the IEC epoch
/// 1970-01-01-00:00:00 (ed. 3, table 10 for LDATE/LDT); TIME_OF_DAY counts from midnight.
struct DateTimeLiteral {
    std::int64_t nanoseconds = 0;
    ElementaryType type = ElementaryType::Date;
};

/// STRING and CHAR hold bytes (`$41` is one byte); WSTRING and WCHAR hold UTF-16 code units.
struct StringLiteral {
    std::variant<std::string, std::u16string> value;
    ElementaryType type = ElementaryType::String;
};

/// `Color#Red`.
struct EnumValueLiteral {
    Identifier type_name;
    Identifier value;
};

struct NullLiteral {};

using Literal = std::variant<IntegerLiteral, RealLiteral, BoolLiteral, DurationLiteral,
                             DateTimeLiteral, StringLiteral, EnumValueLiteral, NullLiteral>;

} // namespace eposp::compiler::ast
