#include "eposp/canopen/parameter_store.hpp"

#include "eposp/core/durable_file.hpp"
#include "eposp/canopen/predefined_connection_set.hpp"
#include "parameter_file.hpp"

#include <fmt/format.h>
#include <utility>

namespace eposp::canopen {
namespace {

template <typename Visit>
void for_each_persistent(const ObjectDictionary& dictionary, Visit visit) {
    for (const auto& [index, object] : dictionary.objects()) {
        for (const auto& [sub_index, sub] : object.subs) {
            if (sub.persistent) {
                visit(index, sub_index, sub);
            }
        }
    }
}

std::string object_name(std::uint16_t index, std::uint8_t sub_index) {
    return fmt::format("{:04X}sub{:X}", index, sub_index);
}

// Every entry must be a persistent sub-object whose value the type accepts; checked before
// anything is applied, so that a store is applied entirely or not at all.
std::optional<std::string> check_entries(const ObjectDictionary& dictionary,
                                         const ParameterFile& file) {
    for (const auto& entry : file.entries) {
        const SubObject* sub = dictionary.find(entry.index, entry.sub_index);
        if (sub == nullptr || !sub->persistent) {
            return fmt::format("it holds {}, which is not a persistent object",
                               object_name(entry.index, entry.sub_index));
        }
        const auto size = fixed_size(sub->type);
        if (size ? entry.value.size() != *size : entry.value.size() > sub->max_length) {
            return fmt::format("the value of {} has the wrong length",
                               object_name(entry.index, entry.sub_index));
        }
    }
    return std::nullopt;
}

} // namespace

ParameterStore::ParameterStore(ObjectDictionary& dictionary, std::filesystem::path file)
    : dictionary_(dictionary), file_(std::move(file)) {}

std::uint32_t ParameterStore::layout_id() const {
    Bytes layout;
    for_each_persistent(dictionary_,
                        [&](std::uint16_t index, std::uint8_t sub_index, const SubObject& sub) {
                            const auto type = static_cast<std::uint16_t>(sub.type);
                            layout.insert(layout.end(), {static_cast<std::uint8_t>(index),
                                                         static_cast<std::uint8_t>(index >> 8),
                                                         sub_index, static_cast<std::uint8_t>(type),
                                                         static_cast<std::uint8_t>(type >> 8)});
                        });
    return crc32(layout);
}

Bytes ParameterStore::value_to_store(std::uint16_t index, std::uint8_t sub_index,
                                     const SubObject& sub) const {
    Bytes value = sub.on_read ? sub.on_read() : sub.value;
    if (pdo_cob_id_node_ && sub_index == 1 && sub.type == DataType::Unsigned32) {
        if (const auto cob_id = predefined_pdo_cob_id(index, *pdo_cob_id_node_)) {
            // Keep the flags (valid, RTR, frame) in bits 29..31; replace the 11-bit CAN-ID.
            const auto flags = decode<std::uint32_t>(value) & 0xE000'0000U;
            value = encode(flags | *cob_id);
        }
    }
    return value;
}

AbortCode ParameterStore::save() {
    ParameterFile file;
    file.layout_id = layout_id();
    for_each_persistent(
        dictionary_, [&](std::uint16_t index, std::uint8_t sub_index, const SubObject& sub) {
            file.entries.push_back({index, sub_index, value_to_store(index, sub_index, sub)});
        });
    if (core::write_file_durably(file_, serialize(file))) {
        return AbortCode::HardwareError;
    }
    pdo_cob_id_node_.reset();
    return AbortCode::None;
}

AbortCode ParameterStore::restore_defaults() {
    pdo_cob_id_node_.reset();
    return core::remove_file_durably(file_) ? AbortCode::HardwareError : AbortCode::None;
}

void ParameterStore::restore_pdo_cob_ids_at_next_save(NodeId node_id) {
    pdo_cob_id_node_ = node_id;
}

StoredValuesReport ParameterStore::load_stored_values() {
    dictionary_.reset_to_defaults();
    const auto content = core::read_whole_file(file_);
    if (!content) {
        return {StoredValuesStatus::Corrupt, content.error()};
    }
    if (!content->has_value()) {
        return {StoredValuesStatus::NoneStored, {}};
    }
    const auto parsed = parse_parameter_file(**content);
    if (!parsed) {
        return {StoredValuesStatus::Corrupt, fmt::format("{}: {}", file_.string(), parsed.error())};
    }
    if (parsed->layout_id != layout_id()) {
        return {StoredValuesStatus::LayoutMismatch,
                fmt::format("{}: the parameter store belongs to another object dictionary layout "
                            "(layout {:08X}, this dictionary has {:08X})",
                            file_.string(), parsed->layout_id, layout_id())};
    }
    if (const auto why = check_entries(dictionary_, *parsed)) {
        return {StoredValuesStatus::Corrupt,
                fmt::format("{}: the parameter store does not fit the dictionary: {}",
                            file_.string(), *why)};
    }
    for (const auto& entry : parsed->entries) {
        dictionary_.find(entry.index, entry.sub_index)->value = entry.value;
    }
    return {StoredValuesStatus::Applied, {}};
}

} // namespace eposp::canopen
