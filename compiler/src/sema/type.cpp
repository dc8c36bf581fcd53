#include "eposp/compiler/sema/type.hpp"

namespace eposp::compiler::sema {

using E = ast::ElementaryType;

const Field* Type::field(std::string_view field_name) const {
    for (const Type* type = this; type != nullptr; type = type->base) {
        if (const auto it = type->field_index.find(field_name); it != type->field_index.end()) {
            return &type->fields[it->second];
        }
    }
    return nullptr;
}

void Type::add_field(Field field) {
    field_index.emplace(field.name, static_cast<std::uint32_t>(fields.size()));
    fields.push_back(std::move(field));
}

namespace {

bool elementary_in(const Type& type, std::initializer_list<E> set) {
    if (type.kind != TypeKind::Elementary) {
        return false;
    }
    for (E e : set) {
        if (type.elementary == e) {
            return true;
        }
    }
    return false;
}

/// Rank within a widening chain (figure 11): a value converts implicitly to a type of the same
/// chain with a higher rank.
struct Chain {
    int chain;
    int rank;
};

std::optional<Chain> chain_of(E e) {
    switch (e) {
    case E::Sint:
        return Chain{0, 0};
    case E::Int:
        return Chain{0, 1};
    case E::Dint:
        return Chain{0, 2};
    case E::Lint:
        return Chain{0, 3};
    case E::Usint:
        return Chain{1, 0};
    case E::Uint:
        return Chain{1, 1};
    case E::Udint:
        return Chain{1, 2};
    case E::Ulint:
        return Chain{1, 3};
    case E::Byte:
        return Chain{2, 0};
    case E::Word:
        return Chain{2, 1};
    case E::Dword:
        return Chain{2, 2};
    case E::Lword:
        return Chain{2, 3};
    case E::Real:
        return Chain{3, 0};
    case E::Lreal:
        return Chain{3, 1};
    default:
        return std::nullopt;
    }
}

} // namespace

bool is_integer(const Type& type) {
    return elementary_in(
        type, {E::Sint, E::Int, E::Dint, E::Lint, E::Usint, E::Uint, E::Udint, E::Ulint});
}
bool is_bit_string(const Type& type) {
    return elementary_in(type, {E::Byte, E::Word, E::Dword, E::Lword});
}
bool is_real(const Type& type) {
    return elementary_in(type, {E::Real, E::Lreal});
}
bool is_numeric(const Type& type) {
    return is_integer(type) || is_real(type);
}
bool is_bool(const Type& type) {
    return elementary_in(type, {E::Bool});
}
bool is_time_like(const Type& type) {
    return elementary_in(type, {E::Time, E::Ltime, E::Date, E::Ldate, E::TimeOfDay, E::Ltod,
                                E::DateAndTime, E::Ldt});
}
TimePart time_part(const Type& from, const Type& to) {
    const auto is_date = [](const Type& type) {
        return elementary_in(type, {E::Date, E::Ldate});
    };
    const auto is_time_of_day = [](const Type& type) {
        return elementary_in(type, {E::TimeOfDay, E::Ltod});
    };
    if (is_date(to) && !is_date(from)) {
        return TimePart::Day;
    }
    if (is_time_of_day(to) && !is_time_of_day(from)) {
        return TimePart::TimeOfDay;
    }
    return TimePart::All;
}
std::int64_t number_unit(ast::ElementaryType type) {
    switch (type) {
    case E::Time:
    case E::TimeOfDay:
        return 1'000'000;
    case E::Date:
    case E::DateAndTime:
        return 1'000'000'000;
    default:
        return 1;
    }
}
bool is_signed(const Type& type) {
    return elementary_in(type, {E::Sint, E::Int, E::Dint, E::Lint}) || is_real(type) ||
           is_time_like(type);
}
bool is_scalar(const Type& type) {
    return type.kind == TypeKind::Elementary || type.kind == TypeKind::Enum ||
           type.kind == TypeKind::Reference || type.kind == TypeKind::Null;
}

// vm::NativeType lists the elementary types in ast::ElementaryType's order.
static_assert(static_cast<int>(vm::NativeType::Bool) == static_cast<int>(E::Bool));
static_assert(static_cast<int>(vm::NativeType::Ldt) == static_cast<int>(E::Ldt));
static_assert(static_cast<int>(vm::NativeType::String) == static_cast<int>(E::String));
static_assert(static_cast<int>(vm::NativeType::Wchar) == static_cast<int>(E::Wchar));

vm::stdlib::CharWidth char_width(const Type& type) {
    return type.wide ? vm::stdlib::CharWidth::Wide : vm::stdlib::CharWidth::Narrow;
}

vm::NativeType native_type(const Type& type) {
    if (type.kind == TypeKind::String) {
        return type.wide ? vm::NativeType::Wstring : vm::NativeType::String;
    }
    return static_cast<vm::NativeType>(type.elementary); // an enumeration's is its base
}

vm::Scalar scalar_of(const Type& type) {
    if (type.kind == TypeKind::Reference || type.kind == TypeKind::Null) {
        return vm::Scalar::Ptr;
    }
    return vm::native_scalar(native_type(type));
}

bool same_type(const Type& a, const Type& b) {
    if (&a == &b) {
        return true;
    }
    if (a.renames != nullptr || b.renames != nullptr) {
        return same_type(a.renames != nullptr ? *a.renames : a,
                         b.renames != nullptr ? *b.renames : b);
    }
    if (a.range || b.range) {
        return a.range && b.range && a.elementary == b.elementary &&
               a.range->lower == b.range->lower && a.range->upper == b.range->upper;
    }
    if (a.kind != TypeKind::Array || b.kind != TypeKind::Array || a.size != b.size ||
        a.dimensions.size() != b.dimensions.size()) {
        return false;
    }
    for (std::size_t d = 0; d < a.dimensions.size(); ++d) {
        if (a.dimensions[d].lower != b.dimensions[d].lower ||
            a.dimensions[d].count != b.dimensions[d].count) {
            return false;
        }
    }
    return same_type(*a.element, *b.element);
}

bool conforms(const Type& actual, const Type& formal) {
    return actual.kind == TypeKind::Array && formal.conformant &&
           actual.dimensions.size() == formal.dimensions.size() &&
           same_type(*actual.element, *formal.element);
}

bool converts_implicitly(const Type& from, const Type& to) {
    if (same_type(from, to)) {
        return true;
    }
    if (from.kind == TypeKind::Null) {
        return to.kind == TypeKind::Reference;
    }
    if (from.kind == TypeKind::Elementary && to.kind == TypeKind::Elementary) {
        if (from.elementary == to.elementary) {
            return true;
        }
        // Every time is nanoseconds in 64 bits; each short one widens to its long form.
        if ((from.elementary == E::Time && to.elementary == E::Ltime) ||
            (from.elementary == E::Date && to.elementary == E::Ldate) ||
            (from.elementary == E::TimeOfDay && to.elementary == E::Ltod) ||
            (from.elementary == E::DateAndTime && to.elementary == E::Ldt)) {
            return true;
        }
        const auto f = chain_of(from.elementary);
        const auto t = chain_of(to.elementary);
        if (!f || !t) {
            return from.elementary == E::Bool && t && t->chain == 2; // BOOL widens to BYTE...
        }
        if (f->chain == t->chain) {
            return f->rank <= t->rank;
        }
        // Unsigned to the next wider signed; integers to REAL/LREAL (figure 11).
        if (f->chain == 1 && t->chain == 0) {
            return f->rank < t->rank;
        }
        if ((f->chain == 0 || f->chain == 1) && t->chain == 3) {
            return f->rank <= 1 + t->rank * 2;
        }
        return false;
    }
    if (from.kind == TypeKind::String && to.kind == TypeKind::String) {
        return from.wide == to.wide;
    }
    if (from.kind == TypeKind::Reference && to.kind == TypeKind::Reference) {
        return from.element == to.element || from.element == nullptr || to.element == nullptr;
    }
    return false;
}

const Field* formal_parameter(const Type& frame, const ast::Argument& argument,
                              std::size_t& positional) {
    if (argument.name) {
        const Field* field = frame.field(argument.name->name);
        return field != nullptr && field->declaration != nullptr ? field : nullptr;
    }
    std::size_t seen = 0;
    for (const Field& field : frame.fields) {
        if (field.declaration != nullptr && (field.section == ast::VarSectionKind::Input ||
                                             field.section == ast::VarSectionKind::InOut)) {
            if (seen++ == positional) {
                ++positional;
                return &field;
            }
        }
    }
    return nullptr;
}

} // namespace eposp::compiler::sema
