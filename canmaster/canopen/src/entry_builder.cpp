#include "eposp/canopen/entry_builder.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace eposp::canopen {
namespace {

std::int64_t decode_integer(DataType type, std::span<const std::uint8_t> bytes) {
    std::uint64_t raw = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        raw |= std::uint64_t{bytes[i]} << (8 * i);
    }
    const std::size_t bits = 8 * bytes.size();
    if (is_signed_integer(type) && bits > 0 && bits < 64 && (raw >> (bits - 1)) != 0) {
        raw |= ~std::uint64_t{0} << bits; // sign-extend
    }
    return static_cast<std::int64_t>(raw);
}

} // namespace

Bytes encode_integer(DataType type, std::int64_t value) {
    const auto size = fixed_size(type);
    if (!size || !is_numeric(type) || is_real(type)) {
        throw std::invalid_argument("encode_integer: not an integer type");
    }
    Bytes bytes(*size);
    const auto raw = static_cast<std::uint64_t>(value);
    for (std::size_t i = 0; i < *size; ++i) {
        bytes[i] = static_cast<std::uint8_t>(raw >> (8 * i));
    }
    return bytes;
}

Entry& Entry::range(std::int64_t low, std::int64_t high) {
    sub_.low_limit = encode_integer(sub_.type, low);
    sub_.high_limit = encode_integer(sub_.type, high);
    return *this;
}

Entry& Entry::one_of(std::span<const std::int64_t> values) {
    sub_.low_limit.reset();
    sub_.high_limit.reset();
    set_write_check(
        [type = sub_.type, allowed = std::vector<std::int64_t>(values.begin(), values.end())](
            std::span<const std::uint8_t> value) {
            return std::ranges::find(allowed, decode_integer(type, value)) != allowed.end()
                       ? AbortCode::None
                       : AbortCode::InvalidValue;
        });
    return *this;
}

Entry& Entry::at_most(const ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                      bool symmetric) {
    // The bound is looked up at each write: it may be added after this entry.
    set_write_check(
        [&od, type = sub_.type, index, sub_index, symmetric](std::span<const std::uint8_t> value) {
            const std::int64_t written = decode_integer(type, value);
            const std::int64_t bound =
                decode_integer(od.find(index, sub_index)->type, od.get(index, sub_index));
            if (written > bound) {
                return AbortCode::ValueTooHigh;
            }
            return symmetric && written < -bound ? AbortCode::ValueTooLow : AbortCode::None;
        });
    return *this;
}

void Entry::set_write_check(SubObject::WriteHook check) {
    if (sub_.on_write) {
        throw std::logic_error("Entry: an entry has one write check");
    }
    sub_.on_write = std::move(check);
}

Entry& Entry::rule(SubObject::WriteHook rule) {
    sub_.on_write = [checked = std::move(sub_.on_write),
                     rule = std::move(rule)](std::span<const std::uint8_t> value) {
        if (checked) {
            if (const AbortCode code = checked(value); code != AbortCode::None) {
                return code;
            }
        }
        return rule(value);
    };
    return *this;
}

void set_default(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index, Bytes value) {
    SubObject& entry = *od.find(index, sub_index);
    entry.default_value = value;
    entry.value = std::move(value);
}

Entry& Entry::persistent() {
    sub_.persistent = true;
    return *this;
}

Entry& Entry::pdo_mappable() {
    sub_.pdo_mappable = true;
    return *this;
}

Entry add_var(ObjectDictionary& od, std::uint16_t index, std::string name, DataType type,
              Access access, std::int64_t default_value) {
    return Entry(
        od.add_variable(index, std::move(name), type, access, encode_integer(type, default_value)));
}

Entry add_entry(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index, std::string name,
                DataType type, Access access, std::int64_t default_value) {
    return Entry(od.add_sub(index, sub_index, std::move(name), type, access,
                            encode_integer(type, default_value)));
}

Entry existing_entry(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub_index,
                     std::string name) {
    SubObject* sub = od.find(index, sub_index);
    if (sub == nullptr) {
        throw std::logic_error("existing_entry: the service did not add the object");
    }
    // A VAR object carries its name twice (the object's and sub-index 0's, CiA 306 exports the
    // object's): both take the device's name.
    if (Object& object = *od.find(index); object.code == ObjectCode::Var) {
        object.name = name;
    }
    sub->name = std::move(name);
    return Entry(*sub);
}

} // namespace eposp::canopen
