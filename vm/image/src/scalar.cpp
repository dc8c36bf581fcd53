#include "eposp/vm/scalar.hpp"

namespace eposp::vm {

std::string_view scalar_name(Scalar s) {
    switch (s) {
    case Scalar::Bool:
        return "BOOL";
    case Scalar::I8:
        return "SINT";
    case Scalar::I16:
        return "INT";
    case Scalar::I32:
        return "DINT";
    case Scalar::I64:
        return "LINT";
    case Scalar::U8:
        return "USINT";
    case Scalar::U16:
        return "UINT";
    case Scalar::U32:
        return "UDINT";
    case Scalar::U64:
        return "ULINT";
    case Scalar::F32:
        return "REAL";
    case Scalar::F64:
        return "LREAL";
    case Scalar::Ptr:
        return "POINTER";
    }
    return "?";
}

std::int64_t integer_value(Scalar s, std::span<const std::uint8_t> bytes) {
    std::uint64_t raw = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        raw |= std::uint64_t{bytes[i]} << (8 * i);
    }
    if (!is_signed_integer(s)) {
        return static_cast<std::int64_t>(raw);
    }
    const unsigned unused = 64 - 8 * static_cast<unsigned>(bytes.size());
    return static_cast<std::int64_t>(raw << unused) >> unused;
}

} // namespace eposp::vm
