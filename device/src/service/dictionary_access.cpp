#include "dictionary_access.hpp"

#include <optional>

namespace eposp::device {
namespace {

constexpr std::size_t kObjectValueSize = 4; // WriteObject carries 4 bytes

} // namespace

void DictionaryAccess::upload(std::uint16_t index, std::uint8_t sub_index, Uploaded done) {
    canopen::Bytes value;
    const canopen::AbortCode abort = objects_.read(index, sub_index, value);
    done(static_cast<std::uint32_t>(abort), std::move(value));
}

void DictionaryAccess::download(std::uint16_t index, std::uint8_t sub_index, canopen::Bytes value,
                                bool sized, Downloaded done) {
    if (!sized) {
        // The object takes its type's size of the 4 bytes, or all 4 for a string or DOMAIN (the
        // SDO server does the same with an expedited write without size).
        const canopen::SubObject* entry = objects_.find(index, sub_index);
        const auto fixed = entry ? canopen::fixed_size(entry->type) : std::nullopt;
        value.resize(fixed && *fixed <= kObjectValueSize ? *fixed : kObjectValueSize);
    }
    done(static_cast<std::uint32_t>(objects_.write(index, sub_index, value)));
}

canopen::AbortCode DictionaryAccess::check_write_size(std::uint16_t index, std::uint8_t sub_index,
                                                      std::uint32_t length) const {
    return objects_.check_write_size(index, sub_index, length);
}

void DictionaryAccess::write_aborted(std::uint16_t index, std::uint8_t sub_index,
                                     canopen::AbortCode reason) {
    // A download to 0x1F50 reports the interruption (docs/service-interface.md).
    objects_.write_aborted(index, sub_index, reason);
}

} // namespace eposp::device
