#include "eposp/device/error_entry.hpp"

#include "eposp/canopen/error_history.hpp"
#include "eposp/canopen/node.hpp"

namespace eposp::device {
std::uint32_t ErrorEntry::encode() const {
    return (warning ? 1U << 31 : 0U) | (std::uint32_t{port} & 0x0F) << 24 |
           std::uint32_t{node} << 16 | code;
}

ErrorEntry ErrorEntry::decode(std::uint32_t value) {
    return {.code = static_cast<std::uint16_t>(value),
            .port = static_cast<std::uint8_t>((value >> 24) & 0x0F),
            .node = static_cast<std::uint8_t>(value >> 16),
            .warning = (value >> 31) != 0};
}

void record_error(canopen::ObjectDictionary& od, const ErrorEntry& error) {
    canopen::ErrorHistory history(od);
    history.record(error.encode());
    if (!error.warning) {
        history.set_error_register(history.error_register() |
                                   canopen::error_register_bits(error.code));
    }
}

} // namespace eposp::device
