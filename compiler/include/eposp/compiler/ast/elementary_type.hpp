#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace eposp::compiler::ast {

/// The elementary data types of IEC 61131-3 ed. 3, table 10.
enum class ElementaryType {
    Bool,
    Sint,
    Int,
    Dint,
    Lint,
    Usint,
    Uint,
    Udint,
    Ulint,
    Byte,
    Word,
    Dword,
    Lword,
    Real,
    Lreal,
    Time,
    Ltime,
    Date,
    Ldate,
    TimeOfDay,
    Ltod,
    DateAndTime,
    Ldt,
    String,
    Wstring,
    Char,
    Wchar,
};

/// The type named by a keyword such as `DINT`, `TOD` or `time_of_day` (any case).
std::optional<ElementaryType> elementary_type_from_name(std::string_view name);
/// The canonical upper-case name (`TIME_OF_DAY`, not `TOD`).
std::string_view name_of(ElementaryType type);

/// The value range of an integer or bit-string type, inclusive.
struct IntegerRange {
    std::int64_t min;
    std::uint64_t max;
};
/// The range of an ANY_INT or ANY_BIT type (BOOL is 0..1); nothing for other types.
std::optional<IntegerRange> integer_range(ElementaryType type);

bool is_real(ElementaryType type);

} // namespace eposp::compiler::ast
