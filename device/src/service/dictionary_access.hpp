#pragma once

#include "eposp/canopen/object_dictionary.hpp"
#include "object_access.hpp"

namespace eposp::device {

/// The objects of a device's own dictionary, as the service interface reaches them: every
/// access completes at once with the dictionary's abort code.
class DictionaryAccess final : public ObjectAccess {
public:
    explicit DictionaryAccess(canopen::ObjectDictionary& objects) : objects_(objects) {}

    void upload(std::uint16_t index, std::uint8_t sub_index, Uploaded done) override;
    void download(std::uint16_t index, std::uint8_t sub_index, canopen::Bytes value, bool sized,
                  Downloaded done) override;
    canopen::AbortCode check_write_size(std::uint16_t index, std::uint8_t sub_index,
                                        std::uint32_t length) const override;
    void write_aborted(std::uint16_t index, std::uint8_t sub_index,
                       canopen::AbortCode reason) override;
    void cancel() override {} // nothing is ever in flight

private:
    canopen::ObjectDictionary& objects_;
};

} // namespace eposp::device
