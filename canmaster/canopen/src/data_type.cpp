#include "eposp/canopen/data_type.hpp"

namespace eposp::canopen {

std::optional<std::size_t> fixed_size(DataType type) {
    switch (type) {
    case DataType::Boolean:
    case DataType::Integer8:
    case DataType::Unsigned8:
        return 1;
    case DataType::Integer16:
    case DataType::Unsigned16:
        return 2;
    case DataType::Integer24:
    case DataType::Unsigned24:
        return 3;
    case DataType::Integer32:
    case DataType::Unsigned32:
    case DataType::Real32:
        return 4;
    case DataType::Integer40:
    case DataType::Unsigned40:
        return 5;
    case DataType::Integer48:
    case DataType::Unsigned48:
    case DataType::TimeOfDay: // CiA 301 7.1.6.5: 28 bit ms + 4 reserved + 16 bit days
    case DataType::TimeDifference:
        return 6;
    case DataType::Integer56:
    case DataType::Unsigned56:
        return 7;
    case DataType::Integer64:
    case DataType::Unsigned64:
    case DataType::Real64:
        return 8;
    case DataType::VisibleString:
    case DataType::OctetString:
    case DataType::UnicodeString:
    case DataType::Domain:
        return std::nullopt;
    }
    return std::nullopt;
}

std::optional<std::size_t> mapping_bits(DataType type) {
    if (type == DataType::Boolean) {
        return 1;
    }
    const auto bytes = fixed_size(type);
    if (!bytes) {
        return std::nullopt;
    }
    return *bytes * 8;
}

bool is_signed_integer(DataType type) {
    switch (type) {
    case DataType::Integer8:
    case DataType::Integer16:
    case DataType::Integer24:
    case DataType::Integer32:
    case DataType::Integer40:
    case DataType::Integer48:
    case DataType::Integer56:
    case DataType::Integer64:
        return true;
    default:
        return false;
    }
}

bool is_unsigned_integer(DataType type) {
    switch (type) {
    case DataType::Unsigned8:
    case DataType::Unsigned16:
    case DataType::Unsigned24:
    case DataType::Unsigned32:
    case DataType::Unsigned40:
    case DataType::Unsigned48:
    case DataType::Unsigned56:
    case DataType::Unsigned64:
        return true;
    default:
        return false;
    }
}

bool is_real(DataType type) {
    return type == DataType::Real32 || type == DataType::Real64;
}

bool is_numeric(DataType type) {
    return type == DataType::Boolean || is_signed_integer(type) || is_unsigned_integer(type) ||
           is_real(type);
}

std::string_view to_string(DataType type) {
    switch (type) {
    case DataType::Boolean:
        return "BOOLEAN";
    case DataType::Integer8:
        return "INTEGER8";
    case DataType::Integer16:
        return "INTEGER16";
    case DataType::Integer32:
        return "INTEGER32";
    case DataType::Unsigned8:
        return "UNSIGNED8";
    case DataType::Unsigned16:
        return "UNSIGNED16";
    case DataType::Unsigned32:
        return "UNSIGNED32";
    case DataType::Real32:
        return "REAL32";
    case DataType::VisibleString:
        return "VISIBLE_STRING";
    case DataType::OctetString:
        return "OCTET_STRING";
    case DataType::UnicodeString:
        return "UNICODE_STRING";
    case DataType::TimeOfDay:
        return "TIME_OF_DAY";
    case DataType::TimeDifference:
        return "TIME_DIFFERENCE";
    case DataType::Domain:
        return "DOMAIN";
    case DataType::Integer24:
        return "INTEGER24";
    case DataType::Real64:
        return "REAL64";
    case DataType::Integer40:
        return "INTEGER40";
    case DataType::Integer48:
        return "INTEGER48";
    case DataType::Integer56:
        return "INTEGER56";
    case DataType::Integer64:
        return "INTEGER64";
    case DataType::Unsigned24:
        return "UNSIGNED24";
    case DataType::Unsigned40:
        return "UNSIGNED40";
    case DataType::Unsigned48:
        return "UNSIGNED48";
    case DataType::Unsigned56:
        return "UNSIGNED56";
    case DataType::Unsigned64:
        return "UNSIGNED64";
    }
    return "unknown";
}

std::optional<DataType> data_type_from_index(std::uint16_t index) {
    const auto type = static_cast<DataType>(index);
    // to_string() knows exactly the enumerators, so it doubles as the membership test.
    if (to_string(type) == "unknown") {
        return std::nullopt;
    }
    return type;
}

} // namespace eposp::canopen
