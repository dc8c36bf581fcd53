#include "eposp/compiler/ast/elementary_type.hpp"

#include "eposp/compiler/ascii_case.hpp"

#include <array>
#include <limits>

namespace eposp::compiler::ast {

namespace {

struct TypeName {
    std::string_view name;
    ElementaryType type;
};

// IEC 61131-3 ed. 3, table 10, with the short forms TOD, DT, LTOD, LDT of table 10's notes.
constexpr std::array kTypeNames{
    TypeName{"BOOL", ElementaryType::Bool},
    TypeName{"SINT", ElementaryType::Sint},
    TypeName{"INT", ElementaryType::Int},
    TypeName{"DINT", ElementaryType::Dint},
    TypeName{"LINT", ElementaryType::Lint},
    TypeName{"USINT", ElementaryType::Usint},
    TypeName{"UINT", ElementaryType::Uint},
    TypeName{"UDINT", ElementaryType::Udint},
    TypeName{"ULINT", ElementaryType::Ulint},
    TypeName{"BYTE", ElementaryType::Byte},
    TypeName{"WORD", ElementaryType::Word},
    TypeName{"DWORD", ElementaryType::Dword},
    TypeName{"LWORD", ElementaryType::Lword},
    TypeName{"REAL", ElementaryType::Real},
    TypeName{"LREAL", ElementaryType::Lreal},
    TypeName{"TIME", ElementaryType::Time},
    TypeName{"LTIME", ElementaryType::Ltime},
    TypeName{"DATE", ElementaryType::Date},
    TypeName{"LDATE", ElementaryType::Ldate},
    TypeName{"TIME_OF_DAY", ElementaryType::TimeOfDay},
    TypeName{"TOD", ElementaryType::TimeOfDay},
    TypeName{"LTIME_OF_DAY", ElementaryType::Ltod},
    TypeName{"LTOD", ElementaryType::Ltod},
    TypeName{"DATE_AND_TIME", ElementaryType::DateAndTime},
    TypeName{"DT", ElementaryType::DateAndTime},
    TypeName{"LDATE_AND_TIME", ElementaryType::Ldt},
    TypeName{"LDT", ElementaryType::Ldt},
    TypeName{"STRING", ElementaryType::String},
    TypeName{"WSTRING", ElementaryType::Wstring},
    TypeName{"CHAR", ElementaryType::Char},
    TypeName{"WCHAR", ElementaryType::Wchar},
};

template <typename T>
constexpr IntegerRange range_of() {
    return {static_cast<std::int64_t>(std::numeric_limits<T>::min()),
            static_cast<std::uint64_t>(std::numeric_limits<T>::max())};
}

} // namespace

std::optional<ElementaryType> elementary_type_from_name(std::string_view name) {
    for (const TypeName& entry : kTypeNames) {
        if (equal_ignoring_case(entry.name, name)) {
            return entry.type;
        }
    }
    return std::nullopt;
}

std::string_view name_of(ElementaryType type) {
    // The first entry of a type is its canonical name.
    for (const TypeName& entry : kTypeNames) {
        if (entry.type == type) {
            return entry.name;
        }
    }
    return "?";
}

std::optional<IntegerRange> integer_range(ElementaryType type) {
    switch (type) {
    case ElementaryType::Bool:
        return IntegerRange{0, 1};
    case ElementaryType::Sint:
        return range_of<std::int8_t>();
    case ElementaryType::Int:
        return range_of<std::int16_t>();
    case ElementaryType::Dint:
        return range_of<std::int32_t>();
    case ElementaryType::Lint:
        return range_of<std::int64_t>();
    case ElementaryType::Usint:
    case ElementaryType::Byte:
        return range_of<std::uint8_t>();
    case ElementaryType::Uint:
    case ElementaryType::Word:
        return range_of<std::uint16_t>();
    case ElementaryType::Udint:
    case ElementaryType::Dword:
        return range_of<std::uint32_t>();
    case ElementaryType::Ulint:
    case ElementaryType::Lword:
        return range_of<std::uint64_t>();
    default:
        return std::nullopt;
    }
}

bool is_real(ElementaryType type) {
    return type == ElementaryType::Real || type == ElementaryType::Lreal;
}

} // namespace eposp::compiler::ast
