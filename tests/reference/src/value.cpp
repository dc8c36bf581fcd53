#include "value.hpp"

namespace eposp::reference {

using E = compiler::ast::ElementaryType;

Value* Value::member(const std::string& folded) {
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == folded) {
            return &elements[i];
        }
    }
    return nullptr;
}

const Value* Value::member(const std::string& folded) const {
    return const_cast<Value*>(this)->member(folded);
}

Shape shape_of(const sema::Type& type) {
    switch (type.kind) {
    case sema::TypeKind::Elementary:
    case sema::TypeKind::Enum:
        switch (type.elementary) {
        case E::Real:
            return Shape::Real;
        case E::Lreal:
            return Shape::Lreal;
        case E::Wchar:
        case E::Wstring:
        case E::String:
            return Shape::Unsupported;
        default:
            return Shape::Integer;
        }
    case sema::TypeKind::String:
        return type.wide ? Shape::Unsupported : Shape::String;
    case sema::TypeKind::Array:
        return type.conformant ? Shape::Unsupported : Shape::Array;
    case sema::TypeKind::Struct:
    case sema::TypeKind::Instance:
        return Shape::Record;
    default:
        return Shape::Unsupported;
    }
}

unsigned width_of(const sema::Type& type) {
    if (type.elementary == E::Bool) {
        return 1;
    }
    return type.size * 8;
}

bool signed_type(const sema::Type& type) {
    return sema::is_signed(type) || sema::is_time_like(type);
}

bool is_decimal(const sema::Type& type) {
    return type.kind == sema::TypeKind::Elementary && sema::is_integer(type);
}

std::uint64_t wrap(std::uint64_t raw, unsigned width, bool is_signed) {
    if (width >= 64) {
        return raw;
    }
    const std::uint64_t mask = (std::uint64_t{1} << width) - 1;
    raw &= mask;
    if (is_signed && (raw >> (width - 1)) != 0) {
        raw |= ~mask;
    }
    return raw;
}

Value integer(const sema::Type& type, std::uint64_t raw) {
    Value value;
    value.type = &type;
    value.bits = type.elementary == E::Bool ? (raw != 0 ? 1 : 0)
                                            : wrap(raw, width_of(type), signed_type(type));
    return value;
}

Value real(const sema::Type& type, double number) {
    Value value;
    value.type = &type;
    value.real =
        type.elementary == E::Real ? static_cast<double>(static_cast<float>(number)) : number;
    return value;
}

Value text(const sema::Type& type, std::string characters) {
    Value value;
    value.type = &type;
    if (characters.size() > type.capacity) {
        characters.resize(type.capacity);
    }
    value.text = std::move(characters);
    return value;
}

std::int64_t since_midnight(std::int64_t ns) {
    constexpr std::int64_t kNsPerDay = 86'400'000'000'000;
    const std::int64_t r = ns % kNsPerDay;
    return r < 0 ? r + kNsPerDay : r;
}

} // namespace eposp::reference
