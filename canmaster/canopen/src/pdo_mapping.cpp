#include "eposp/canopen/pdo_mapping.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

namespace eposp::canopen {
namespace {

template <typename Word>
Word load_native(const std::uint8_t* bytes) {
    Word word;
    std::memcpy(&word, bytes, sizeof word);
    return word;
}

std::uint64_t low_bits_mask(std::size_t bits) {
    return bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
}

// A payload of up to 8 bytes as one little-endian word, so that a field is a shift and a mask.
// Every TPDO loads its mapped values at every SYNC: the common sizes are one load each.
std::uint64_t load_le(std::span<const std::uint8_t> bytes) {
    if constexpr (std::endian::native == std::endian::little) {
        switch (bytes.size()) {
        case 1:
            return bytes[0];
        case 2:
            return load_native<std::uint16_t>(bytes.data());
        case 4:
            return load_native<std::uint32_t>(bytes.data());
        default:
            if (bytes.size() >= 8) {
                return load_native<std::uint64_t>(bytes.data());
            }
        }
    }
    std::uint64_t word = 0;
    for (std::size_t i = 0; i < bytes.size() && i < 8; ++i) {
        word |= std::uint64_t{bytes[i]} << (8 * i);
    }
    return word;
}

void store_le(std::uint64_t word, std::span<std::uint8_t> bytes) {
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        bytes[i] = static_cast<std::uint8_t>(word >> (8 * i));
    }
}

bool is_integer(DataType type) {
    return is_signed_integer(type) || is_unsigned_integer(type);
}

// The length rule shared by real objects and dummies: 1..type bits, shorter only for integers.
AbortCode check_length(DataType type, std::uint8_t bits) {
    const auto type_bits = mapping_bits(type);
    if (!type_bits || bits == 0 || bits > *type_bits) {
        return AbortCode::NotMappable;
    }
    if (bits < *type_bits && !is_integer(type)) {
        return AbortCode::NotMappable;
    }
    return AbortCode::None;
}

// The value's bits as the PDO carries them: BOOLEAN as one bit, anything else truncated to the
// mapped length.
std::uint64_t to_field(DataType type, std::span<const std::uint8_t> value, std::size_t bits) {
    if (type == DataType::Boolean) {
        return value.empty() || value[0] == 0 ? 0 : 1;
    }
    return load_le(value) & low_bits_mask(bits);
}

// The inverse of to_field for a value of `type`: a short signed integer is sign-extended.
Bytes from_field(DataType type, std::uint64_t field, std::size_t bits) {
    if (type == DataType::Boolean) {
        return Bytes{static_cast<std::uint8_t>(field & 1)};
    }
    const std::size_t size = *fixed_size(type);
    if (is_signed_integer(type) && bits < 64 && (field >> (bits - 1) & 1) != 0) {
        field |= ~low_bits_mask(bits);
    }
    Bytes value(size);
    store_le(field, value);
    return value;
}

} // namespace

MappingEntry MappingEntry::from_raw(std::uint32_t raw) {
    return {static_cast<std::uint16_t>(raw >> 16), static_cast<std::uint8_t>(raw >> 8),
            static_cast<std::uint8_t>(raw)};
}

std::uint32_t MappingEntry::raw() const {
    return std::uint32_t{index} << 16 | std::uint32_t{sub_index} << 8 | bits;
}

bool is_dummy(MappingEntry entry) {
    return entry.index >= 0x0002 && entry.index <= 0x0007;
}

AbortCode check_mapping_entry(const ObjectDictionary& od, MappingEntry entry,
                              PdoDirection direction) {
    if (direction == PdoDirection::Receive && is_dummy(entry)) {
        return check_length(static_cast<DataType>(entry.index), entry.bits);
    }
    const SubObject* sub = od.find(entry.index, entry.sub_index);
    if (sub == nullptr) {
        return AbortCode::ObjectDoesNotExist;
    }
    const bool accessible =
        direction == PdoDirection::Receive ? writable(sub->access) : readable(sub->access);
    if (!sub->pdo_mappable || !accessible) {
        return AbortCode::NotMappable;
    }
    return check_length(sub->type, entry.bits);
}

PdoMapping::Resolution PdoMapping::resolve(const ObjectDictionary& od,
                                           std::span<const MappingEntry> entries,
                                           PdoDirection direction) {
    Resolution result;
    PdoMapping& mapping = result.mapping;
    for (const MappingEntry& entry : entries) {
        if (const AbortCode fault = check_mapping_entry(od, entry, direction);
            fault != AbortCode::None) {
            return {fault, {}};
        }
        if (mapping.bits_ + entry.bits > kMaxPdoBits) {
            return {AbortCode::PdoLengthExceeded, {}};
        }
        const bool dummy = direction == PdoDirection::Receive && is_dummy(entry);
        const SubObject* sub = dummy ? nullptr : od.find(entry.index, entry.sub_index);
        const DataType type = dummy ? static_cast<DataType>(entry.index) : sub->type;
        mapping.fields_.push_back({entry, type, mapping.bits_, dummy, sub});
        mapping.bits_ += entry.bits;
    }
    return result;
}

bool PdoMapping::maps(std::uint16_t index, std::uint8_t sub_index) const {
    return std::any_of(fields_.begin(), fields_.end(), [&](const Field& field) {
        return !field.dummy && field.entry.index == index && field.entry.sub_index == sub_index;
    });
}

std::vector<std::uint16_t> PdoMapping::mapped_indices() const {
    std::vector<std::uint16_t> indices;
    for (const Field& field : fields_) {
        if (!field.dummy &&
            std::find(indices.begin(), indices.end(), field.entry.index) == indices.end()) {
            indices.push_back(field.entry.index);
        }
    }
    return indices;
}

PdoPayload PdoMapping::pack() const {
    std::uint64_t word = 0;
    for (const Field& field : fields_) {
        // Read as ObjectDictionary::get() reads, without its lookup: every TPDO packs at every
        // SYNC. A stored value is read in place.
        const SubObject& sub = *field.sub;
        const std::uint64_t bits = sub.on_read
                                       ? to_field(field.type, sub.on_read(), field.entry.bits)
                                       : to_field(field.type, sub.value, field.entry.bits);
        word |= bits << field.offset;
    }
    PdoPayload payload;
    payload.size = size();
    // The fields end within size() bytes, so the word's bytes beyond it are the payload's zeros.
    if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(payload.data.data(), &word, sizeof word);
    } else {
        store_le(word, std::span(payload.data).first(payload.size));
    }
    return payload;
}

void PdoMapping::unpack(ObjectDictionary& od, std::span<const std::uint8_t> payload) const {
    const std::uint64_t word = load_le(payload.first(size()));
    for (const Field& field : fields_) {
        if (field.dummy) {
            continue;
        }
        const std::uint64_t bits = word >> field.offset & low_bits_mask(field.entry.bits);
        od.set(field.entry.index, field.entry.sub_index,
               from_field(field.type, bits, field.entry.bits));
    }
}

} // namespace eposp::canopen
