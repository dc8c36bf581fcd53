#include "native_value_text.hpp"

#include "eposp/vm/value_format.hpp"

#include <cmath>
#include <fmt/format.h>

namespace eposp::plctest {
namespace {

using vm::NativeType;

enum class Kind {
    Boolean,
    Signed,
    Unsigned,
    Real,
    Duration,
    Date,
    TimeOfDay,
    DateAndTime,
    Text,
    Character
};

Kind kind_of(NativeType type) {
    switch (type) {
    case NativeType::Bool:
        return Kind::Boolean;
    case NativeType::Sint:
    case NativeType::Int:
    case NativeType::Dint:
    case NativeType::Lint:
        return Kind::Signed;
    case NativeType::Usint:
    case NativeType::Uint:
    case NativeType::Udint:
    case NativeType::Ulint:
    case NativeType::Byte:
    case NativeType::Word:
    case NativeType::Dword:
    case NativeType::Lword:
        return Kind::Unsigned;
    case NativeType::Real:
    case NativeType::Lreal:
        return Kind::Real;
    case NativeType::Time:
    case NativeType::Ltime:
        return Kind::Duration;
    case NativeType::Date:
    case NativeType::Ldate:
        return Kind::Date;
    case NativeType::TimeOfDay:
    case NativeType::Ltod:
        return Kind::TimeOfDay;
    case NativeType::DateAndTime:
    case NativeType::Ldt:
        return Kind::DateAndTime;
    case NativeType::String:
    case NativeType::Wstring:
        return Kind::Text;
    case NativeType::Char:
    case NativeType::Wchar:
        return Kind::Character;
    }
    return Kind::Unsigned;
}

std::int64_t signed_value(const vm::NativeValue& v) {
    switch (v.bytes.size()) {
    case 1:
        return v.as<std::int8_t>();
    case 2:
        return v.as<std::int16_t>();
    case 4:
        return v.as<std::int32_t>();
    default:
        return v.as<std::int64_t>();
    }
}

std::uint64_t unsigned_value(const vm::NativeValue& v) {
    switch (v.bytes.size()) {
    case 1:
        return v.as<std::uint8_t>();
    case 2:
        return v.as<std::uint16_t>();
    case 4:
        return v.as<std::uint32_t>();
    default:
        return v.as<std::uint64_t>();
    }
}

long double real_value(const vm::NativeValue& v) {
    switch (kind_of(v.type)) {
    case Kind::Real:
        return v.bytes.size() == 4 ? v.as<float>() : v.as<double>();
    case Kind::Signed:
        return static_cast<long double>(signed_value(v));
    default:
        return static_cast<long double>(unsigned_value(v));
    }
}

bool is_number(Kind kind) {
    return kind == Kind::Signed || kind == Kind::Unsigned || kind == Kind::Real;
}

// Integers of any width and signedness compare by their mathematical value.
bool integers_equal(const vm::NativeValue& a, Kind a_kind, const vm::NativeValue& b, Kind b_kind) {
    if (a_kind == Kind::Signed && b_kind == Kind::Signed) {
        return signed_value(a) == signed_value(b);
    }
    if (a_kind == Kind::Unsigned && b_kind == Kind::Unsigned) {
        return unsigned_value(a) == unsigned_value(b);
    }
    const auto& [s, u] = a_kind == Kind::Signed ? std::pair(&a, &b) : std::pair(&b, &a);
    const std::int64_t value = signed_value(*s);
    return value >= 0 && static_cast<std::uint64_t>(value) == unsigned_value(*u);
}

} // namespace

std::string literal(const vm::NativeValue& value) {
    // Bit strings read best as the hexadecimal literals they are usually written as.
    if (value.type == NativeType::Byte || value.type == NativeType::Word ||
        value.type == NativeType::Dword || value.type == NativeType::Lword) {
        return fmt::format("16#{:0{}X}", unsigned_value(value), value.bytes.size() * 2);
    }
    vm::TypeDescriptor type;
    type.name = std::string(vm::native_type_name(value.type));
    if (value.is_string()) {
        type.kind = vm::TypeKind::String;
    } else {
        type.scalar = vm::native_scalar(value.type);
        type.size = static_cast<std::uint32_t>(value.bytes.size());
    }
    if (value.bytes.size() < (value.is_string() ? 4U : vm::scalar_size(type.scalar))) {
        return "<" + type.name + ">"; // only a corrupt image passes fewer bytes
    }
    return vm::format_value(type, value.bytes);
}

Comparison compare(const vm::NativeValue& expected, const vm::NativeValue& actual) {
    const Kind e = kind_of(expected.type);
    const Kind a = kind_of(actual.type);
    if (is_number(e) && is_number(a)) {
        if (e == Kind::Real || a == Kind::Real) {
            return {real_value(expected) == real_value(actual), false};
        }
        return {integers_equal(expected, e, actual, a), false};
    }
    if (e != a) {
        return {false, true};
    }
    switch (e) {
    case Kind::Text:
        return {expected.text() == actual.text(), false};
    case Kind::Boolean:
        return {(expected.as<std::uint8_t>() != 0) == (actual.as<std::uint8_t>() != 0), false};
    case Kind::Character:
        return {unsigned_value(expected) == unsigned_value(actual), false};
    default:
        return {expected.as<std::int64_t>() == actual.as<std::int64_t>(), false};
    }
}

} // namespace eposp::plctest
