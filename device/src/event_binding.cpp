#include "eposp/device/event_binding.hpp"

#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/vm/process_image.hpp"
#include "text_words.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <string>
#include <vector>

namespace eposp::device {

namespace {

// "internal" or "can" in front of the rest, taken off `words`; the CAN port without one.
std::uint8_t take_port(std::vector<std::string>& words) {
    if (!words.empty() && (lower(words.front()) == "internal" || lower(words.front()) == "can")) {
        const bool internal = lower(words.front()) == "internal";
        words.erase(words.begin());
        return internal ? kInternalPort : kExternalPort;
    }
    return kExternalPort;
}

constexpr std::string_view kForms =
    "an event is 'sync', 'rpdo [internal|can] N', 'emcy [internal|can] [NODE]' or "
    "'input %IXbyte.bit'";

} // namespace

std::size_t last_rpdo(std::uint8_t port) {
    return port == kInternalPort ? 4 : 32;
}

std::optional<std::pair<std::uint32_t, std::uint8_t>> parse_input_bit(std::string_view text) {
    unsigned byte = 0;
    unsigned bit = 0;
    char end = 0;
    const std::string copy(text);
    if (std::sscanf(copy.c_str(), "%%IX%u.%u%c", &byte, &bit, &end) != 2 ||
        byte >= vm::kProcessImageSize || bit > 7) {
        return std::nullopt;
    }
    return std::pair{static_cast<std::uint32_t>(byte), static_cast<std::uint8_t>(bit)};
}

core::Result<EventBinding> parse_event(std::string_view text) {
    std::vector<std::string> words = words_of(text);
    if (words.empty()) {
        return core::Error{std::string(kForms)};
    }
    const std::string kind = lower(words.front());
    words.erase(words.begin());
    EventBinding event;
    if (kind == "sync" && words.empty()) {
        event.source = EventBinding::Source::Sync;
    } else if (kind == "rpdo") {
        event.source = EventBinding::Source::Rpdo;
        event.port = take_port(words);
        const auto rpdo = words.size() == 1 ? number(words.front()) : std::nullopt;
        if (!rpdo || *rpdo < 1 || *rpdo > last_rpdo(event.port)) {
            return core::Error{"an rpdo event names the RPDO: 1..32 on the CAN port, 1..4 on "
                               "the internal one ('rpdo internal 1')"};
        }
        event.rpdo = *rpdo;
    } else if (kind == "emcy") {
        event.source = EventBinding::Source::Emcy;
        event.port = take_port(words);
        if (!words.empty()) {
            const auto node = words.size() == 1 ? number(words.front()) : std::nullopt;
            if (!node || *node < 1 || *node > canopen::kMaxNodeId) {
                return core::Error{"an emcy event names no node (any) or a node-ID 1..127"};
            }
            event.node = static_cast<canopen::NodeId>(*node);
        }
    } else if (kind == "input") {
        event.source = EventBinding::Source::Input;
        const auto bit = words.size() == 1 ? parse_input_bit(words.front()) : std::nullopt;
        if (!bit) {
            return core::Error{
                fmt::format("an input event names a process input bit %IX0.0 .. %IX{}.7",
                            vm::kProcessImageSize - 1)};
        }
        event.input_byte = bit->first;
        event.input_bit = bit->second;
    } else {
        return core::Error{std::string(kForms)};
    }
    return event;
}

} // namespace eposp::device
