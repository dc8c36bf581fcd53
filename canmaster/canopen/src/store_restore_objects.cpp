#include "eposp/canopen/store_restore_objects.hpp"

#include <utility>

namespace eposp::canopen {
namespace {

// CiA 301 7.5.2.13/14: bit 0 of the value read is "saves on command" / "restores defaults".
constexpr std::uint32_t kOnCommand = 0x0000'0001;

SubObject& add_command(ObjectDictionary& dictionary, std::uint16_t index, std::uint8_t sub_index,
                       std::string name) {
    SubObject& sub = dictionary.add_sub(index, sub_index, std::move(name), DataType::Unsigned32,
                                        Access::ReadWrite, encode(kOnCommand));
    sub.on_read = [] {
        return encode(kOnCommand);
    };
    return sub;
}

// CiA 301 7.5.2.13: "If a wrong signature is written, the CANopen device refuses to store and
// responds with abort code 0800 002xh."
bool is_signature(std::span<const std::uint8_t> value, std::uint32_t signature) {
    return decode<std::uint32_t>(value) == signature;
}

AbortCode permitted(const StoreRestoreOptions& options) {
    return options.restore_permitted ? options.restore_permitted() : AbortCode::None;
}

} // namespace

void add_store_restore_objects(ObjectDictionary& dictionary, ParameterStore& store,
                               StoreRestoreOptions options) {
    dictionary.add_object(0x1010, "Store Parameters", ObjectCode::Array);
    add_command(dictionary, 0x1010, 1, "Save all Parameters").on_write =
        [&store](std::span<const std::uint8_t> value) {
            return is_signature(value, kSaveSignature) ? store.save() : AbortCode::TransferOrStore;
        };

    dictionary.add_object(0x1011, "Restore Default Parameters", ObjectCode::Array);
    add_command(dictionary, 0x1011, 1, "Restore all Default Parameters").on_write =
        [&store, options = std::move(options)](std::span<const std::uint8_t> value) {
            if (!is_signature(value, kLoadSignature)) {
                return AbortCode::TransferOrStore;
            }
            if (const AbortCode refused = permitted(options); refused != AbortCode::None) {
                return refused;
            }
            return store.restore_defaults();
        };
}

void add_restore_pdo_cob_ids_object(ObjectDictionary& dictionary, ParameterStore& store,
                                    std::function<NodeId()> node_id, StoreRestoreOptions options) {
    add_command(dictionary, 0x1011, 5, "Restore Default PDO COB-IDs").on_write =
        [&store, node_id = std::move(node_id),
         options = std::move(options)](std::span<const std::uint8_t> value) {
            if (!is_signature(value, kLoadSignature)) {
                return AbortCode::TransferOrStore;
            }
            if (const AbortCode refused = permitted(options); refused != AbortCode::None) {
                return refused;
            }
            store.restore_pdo_cob_ids_at_next_save(node_id());
            return AbortCode::None;
        };
    // EPOS2 firmware specification 8.2.9: sub-index 0 of 0x1011 gives the "Number of entries"
    // (0x02 for sub-indices 1 and 5), not the highest sub-index.
    Object& object = *dictionary.find(0x1011);
    SubObject& entries = object.subs.at(0);
    entries.default_value = encode(static_cast<std::uint8_t>(object.subs.size() - 1));
    entries.value = entries.default_value;
}

void add_erase_program_object(ObjectDictionary& dictionary, std::function<AbortCode()> erase) {
    add_command(dictionary, 0x1011, 2, "Erase Application Program").on_write =
        [erase = std::move(erase)](std::span<const std::uint8_t> value) {
            return is_signature(value, kEraseSignature) ? erase() : AbortCode::TransferOrStore;
        };
}

} // namespace eposp::canopen
