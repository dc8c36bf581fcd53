#pragma once

#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/core/result.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::device {

/// A device event that releases an event task of the program (docs/network.md, "Events"): named
/// by the network file, or by the program's TASK (`{attribute 'event' := 'rpdo 1'}`).
struct EventBinding {
    enum class Source : std::uint8_t {
        Sync,  ///< each SYNC the EPOS P sends
        Emcy,  ///< an EMCY from `node` (any node without one) on `port`
        Rpdo,  ///< the data of RPDO `rpdo` of `port` stored
        Input, ///< a rising edge of process input bit %IX`input_byte`.`input_bit`
    };
    std::string task;
    Source source = Source::Sync;
    std::uint8_t port = 2;
    std::optional<canopen::NodeId> node;
    std::size_t rpdo = 0;
    std::uint32_t input_byte = 0;
    std::uint8_t input_bit = 0;
};

/// The highest RPDO number of a port: 32 on the CAN port, 4 on the internal one.
std::size_t last_rpdo(std::uint8_t port);

/// "%IX4.2": byte 4, bit 2 of the process input image; none if the text is not such a bit or
/// the byte is outside the image.
std::optional<std::pair<std::uint32_t, std::uint8_t>> parse_input_bit(std::string_view text);

/// The event a TASK's attribute names, for no task yet: `sync`, `rpdo [internal|can] N`,
/// `emcy [internal|can] [NODE]`, `input %IXbyte.bit` (keywords in any case). The error says
/// what is wrong, without the text itself.
core::Result<EventBinding> parse_event(std::string_view text);

} // namespace eposp::device
