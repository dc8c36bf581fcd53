#pragma once

#include "eposp/compiler/ast/declarations.hpp"
#include "eposp/compiler/sema/name_map.hpp"
#include "eposp/vm/native_type.hpp"
#include "eposp/vm/scalar.hpp"
#include "eposp/vm/stdlib/string_layout.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::compiler::sema {

struct Type;

/// A member of a STRUCT or a variable of an FB/PROGRAM instance, at its byte offset.
struct Field {
    std::string name{}; // as declared; compared case-insensitively
    const Type* type = nullptr;
    std::uint32_t offset = 0;
    ast::VarSectionKind section = ast::VarSectionKind::Var;
    const ast::VariableDeclaration* declaration = nullptr; // null for generated fields
};

struct ArrayDimension {
    std::int64_t lower = 0;
    std::uint32_t count = 0;
};

/// The bounds of a subrange type (6.4.4.4), both included.
struct ValueRange {
    std::int64_t lower = 0;
    std::int64_t upper = 0;

    bool contains(std::int64_t value) const { return lower <= value && value <= upper; }
    bool contains(const ValueRange& other) const {
        return lower <= other.lower && other.upper <= upper;
    }
};

enum class TypeKind {
    Elementary, ///< IEC 61131-3 ed. 3, table 10 (STRING excepted)
    String,     ///< STRING[n] / WSTRING[n] (6.4.4.1)
    Array,      ///< 6.4.4.5
    Struct,     ///< 6.4.4.6
    Enum,       ///< 6.4.4.2, held in its base type
    Reference,  ///< REF_TO / POINTER TO (6.4.4.10): an address in VM memory
    Instance,   ///< an FB or PROGRAM instance (6.6.3): its variables, base part first
    Null,       ///< the type of NULL, assignable to every reference
};

/// One IEC data type with its memory layout. Aliases are their base type; a subrange is an
/// elementary type with a `range` (its values are checked where stored); an FB
/// that EXTENDS another lays its base's instance out first, so the base part of a derived
/// instance is a valid base instance (ed. 3, 6.6.5).
struct Type {
    TypeKind kind = TypeKind::Elementary;
    std::string name{};
    ast::ElementaryType elementary = ast::ElementaryType::Bool; ///< Elementary, Enum (its base)
    std::uint32_t size = 0;
    std::uint32_t align = 1;
    std::uint32_t capacity = 0;               ///< String
    bool wide = false;                        ///< String: WSTRING
    const Type* element = nullptr;            ///< Array element, Reference target
    std::vector<ArrayDimension> dimensions{}; ///< Array
    std::vector<Field> fields{};              ///< Struct, Instance
    const ast::Pou* pou = nullptr;            ///< Instance
    const Type* base = nullptr;               ///< Instance: the FB it EXTENDS
    std::vector<std::pair<std::string, std::int64_t>> enumerators{}; ///< Enum
    std::optional<ValueRange> range{}; ///< Elementary: the bounds of a subrange
    /// The default initial value its type declaration gives (6.4.2); null: the usual default.
    const ast::Initializer* initial_value = nullptr;
    /// A declared type with its own default made of a shared type (`TYPE Speed : INT := 100`):
    /// that type, the same type as this one; null otherwise.
    const Type* renames = nullptr;
    /// Array: ARRAY[*, ...], whose bounds are known only when running (6.5.3); `dimensions`
    /// then only counts them. Struct: the reference a VAR_IN_OUT of it is passed by.
    bool conformant = false;
    /// Struct: ANY, the generic input of a native function (a FUNCTION without statements in a
    /// linked library), passed as the value's address and a descriptor of its type.
    bool generic = false;

    /// The field `name` (case-insensitive), searching the base part too.
    const Field* field(std::string_view field_name) const;
    /// Appends `field` to `fields` and to the index `field` searches (the first of a name wins).
    void add_field(Field field);

    /// Struct, Instance: each field's position in `fields` by name.
    NameMap<std::uint32_t> field_index{};
};

bool is_integer(const Type& type);    ///< ANY_INT
bool is_bit_string(const Type& type); ///< ANY_BIT without BOOL
bool is_real(const Type& type);       ///< ANY_REAL
bool is_numeric(const Type& type);    ///< ANY_NUM
bool is_bool(const Type& type);
bool is_time_like(const Type& type); ///< TIME, LTIME, DATE, TOD, DT and long forms
/// What a conversion between two times or dates keeps of its nanoseconds.
enum class TimePart : std::uint8_t {
    All,       ///< the same nanoseconds (TOD_TO_DT, DATE_TO_LDATE, TIME_TO_LTIME...)
    Day,       ///< the day at midnight, as DT_TO_DATE: a DATE or LDATE made of any other
    TimeOfDay, ///< the time since midnight, as DT_TO_TOD: a TOD or LTOD made of any other
};
TimePart time_part(const Type& from, const Type& to);
/// Nanoseconds per unit when a time converts to or from a number (TIME_TO_DINT, DINT_TO_DT):
/// CODESYS's, TIME and TOD in milliseconds, DATE and DT in seconds, the long forms (and anything
/// else) in nanoseconds.
std::int64_t number_unit(ast::ElementaryType type);
bool is_signed(const Type& type);
/// Types held in one VM scalar (elementary, enum, reference).
bool is_scalar(const Type& type);
/// How wide the characters of a STRING (Narrow) or WSTRING (Wide) type are.
vm::stdlib::CharWidth char_width(const Type& type);
/// The VM's name of an elementary, enumeration (its base) or text type.
vm::NativeType native_type(const Type& type);
/// The VM representation of a scalar type (vm::native_scalar of its native_type; a reference is
/// an address).
vm::Scalar scalar_of(const Type& type);

/// Whether two types are the same: the same object (or one renames the other), arrays of the same
/// bounds and the same element type, or subranges of the same base and bounds (array and subrange
/// types are not interned, each declaration makes its own).
bool same_type(const Type& a, const Type& b);

/// Whether `actual` may be passed to the VAR_IN_OUT ARRAY[*] `formal` (6.5.3): an array, of
/// any bounds, with as many dimensions and the same element type.
bool conforms(const Type& actual, const Type& formal);

/// What a VAR_IN_OUT ARRAY[*] is passed by: the array's address, then the lower bound and
/// the count of each dimension (DINT, UDINT), so its bounds go along with it.
inline constexpr std::uint32_t kConformantBoundsOffset = 8;
inline constexpr std::uint32_t kConformantDimensionSize = 8;

/// IEC 61131-3 ed. 3, 6.6.1.6 figure 11: the implicit widening conversions. True when a value
/// of `from` may be used where `to` is expected without a conversion function.
bool converts_implicitly(const Type& from, const Type& to);

/// The parameter of the function whose frame is `frame` that a call's `argument` binds: by its
/// formal name, or the next input or VAR_IN_OUT when positional (`positional` counts those
/// taken); null when it binds none.
const Field* formal_parameter(const Type& frame, const ast::Argument& argument,
                              std::size_t& positional);

} // namespace eposp::compiler::sema
