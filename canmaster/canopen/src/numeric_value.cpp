#include "numeric_value.hpp"

#include <cmath>
#include <limits>

namespace eposp::canopen {
namespace {

std::uint64_t read_little_endian(std::span<const std::uint8_t> bytes) {
    std::uint64_t raw = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        raw |= std::uint64_t{bytes[i]} << (8 * i);
    }
    return raw;
}

Bytes write_little_endian(std::uint64_t raw, std::size_t size) {
    Bytes bytes(size);
    for (std::size_t i = 0; i < size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(raw >> (8 * i));
    }
    return bytes;
}

std::int64_t sign_extend(std::uint64_t raw, std::size_t size) {
    const unsigned shift = static_cast<unsigned>(64 - 8 * size);
    return static_cast<std::int64_t>(raw << shift) >> shift;
}

std::uint64_t unsigned_max(DataType type) {
    if (type == DataType::Boolean) {
        return 1;
    }
    const std::size_t bits = *fixed_size(type) * 8;
    return bits == 64 ? std::numeric_limits<std::uint64_t>::max() : (std::uint64_t{1} << bits) - 1;
}

std::int64_t signed_max(std::size_t size) {
    return static_cast<std::int64_t>((std::uint64_t{1} << (8 * size - 1)) - 1);
}

// The value as a signed integer if it is one exactly (an integral double included).
std::optional<std::int64_t> as_int64(NumericValue value) {
    if (const auto* i = std::get_if<std::int64_t>(&value)) {
        return *i;
    }
    if (const auto* u = std::get_if<std::uint64_t>(&value)) {
        if (*u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
            return std::nullopt;
        }
        return static_cast<std::int64_t>(*u);
    }
    const double d = std::get<double>(value);
    if (std::trunc(d) != d || d < -0x1p63 || d >= 0x1p63) {
        return std::nullopt;
    }
    return static_cast<std::int64_t>(d);
}

std::optional<std::uint64_t> as_uint64(NumericValue value) {
    if (const auto* u = std::get_if<std::uint64_t>(&value)) {
        return *u;
    }
    if (const auto* i = std::get_if<std::int64_t>(&value)) {
        if (*i < 0) {
            return std::nullopt;
        }
        return static_cast<std::uint64_t>(*i);
    }
    const double d = std::get<double>(value);
    if (std::trunc(d) != d || d < 0 || d >= 0x1p64) {
        return std::nullopt;
    }
    return static_cast<std::uint64_t>(d);
}

double as_double(NumericValue value) {
    return std::visit([](auto v) { return static_cast<double>(v); }, value);
}

} // namespace

std::optional<NumericValue> decode_numeric(DataType type, std::span<const std::uint8_t> bytes) {
    const auto size = fixed_size(type);
    if (!is_numeric(type) || !size || bytes.size() != *size) {
        return std::nullopt;
    }
    const std::uint64_t raw = read_little_endian(bytes);
    if (type == DataType::Real32) {
        return static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(raw)));
    }
    if (type == DataType::Real64) {
        return std::bit_cast<double>(raw);
    }
    if (is_signed_integer(type)) {
        return sign_extend(raw, *size);
    }
    return raw;
}

std::optional<Bytes> encode_numeric(DataType type, NumericValue value) {
    const auto size = fixed_size(type);
    if (!is_numeric(type) || !size) {
        return std::nullopt;
    }
    if (type == DataType::Real32) {
        const double d = as_double(value);
        if (std::isfinite(d) && std::abs(d) > std::numeric_limits<float>::max()) {
            return std::nullopt;
        }
        return encode(static_cast<float>(d));
    }
    if (type == DataType::Real64) {
        return encode(as_double(value));
    }
    if (is_signed_integer(type)) {
        const auto i = as_int64(value);
        const std::int64_t max = signed_max(*size);
        if (!i || *i > max || *i < -max - 1) {
            return std::nullopt;
        }
        return write_little_endian(static_cast<std::uint64_t>(*i), *size);
    }
    const auto u = as_uint64(value);
    if (!u || *u > unsigned_max(type)) {
        return std::nullopt;
    }
    return write_little_endian(*u, *size);
}

std::partial_ordering compare(const NumericValue& a, const NumericValue& b) {
    if (const auto* x = std::get_if<std::int64_t>(&a), *y = std::get_if<std::int64_t>(&b); x && y) {
        return *x <=> *y;
    }
    if (const auto* x = std::get_if<std::uint64_t>(&a), *y = std::get_if<std::uint64_t>(&b);
        x && y) {
        return *x <=> *y;
    }
    return as_double(a) <=> as_double(b);
}

} // namespace eposp::canopen
