#pragma once

#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/core/result.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::device {

/// One end of a wire between the machine's devices (docs/network.md, "Wires"): a digital or
/// analog input or output of a simulated EPOS2 or ESCON2, or a bit or word of the EPOS P's
/// process image.
struct SignalEnd {
    enum class Device : std::uint8_t {
        ProcessImage, ///< the EPOS P's DS-405 process image: %IX/%QX bits, %IW/%QW words (mV)
        Epos2,        ///< a simulated EPOS2: the internal one, or a slave on the CAN bus
        Escon2,       ///< a simulated ESCON2, by its name in the network file
    };
    enum class Kind : std::uint8_t { Digital, Analog };
    enum class Direction : std::uint8_t { Input, Output };

    Device device = Device::ProcessImage;
    Kind kind = Kind::Digital;
    Direction direction = Direction::Input;
    std::uint8_t port = 2;    ///< an EPOS2's: 1 the internal one, 2 the CAN bus
    canopen::NodeId node = 0; ///< an EPOS2's node-ID
    std::string name;         ///< an ESCON2's
    /// A drive's input or output (from 1; an ESCON2's high-speed pins follow its regular ones,
    /// as Escon2Drive numbers them); %IW/%QW's word.
    std::uint32_t number = 0;
    std::uint32_t byte = 0; ///< %IX/%QX's byte
    std::uint8_t bit = 0;   ///< %IX/%QX's bit

    friend bool operator==(const SignalEnd&, const SignalEnd&) = default;
};

/// A wire: what `to` receives is what `from` puts out, sampled every millisecond.
struct SignalWire {
    SignalEnd from;
    SignalEnd to;
};

/// Reads one end: `%QX0.3`, `%IW16`, `internal digital output 2`, `node 3 digital input 5`,
/// `node 3 analog input 1`, `escon2 conveyor high-speed digital input 1`, `escon2 conveyor
/// analog output 2` (keywords in any case). The error says which forms there are, or which
/// number is out of range (an EPOS2 24/5 has digital inputs 1..6, outputs 1..4, analog inputs
/// 1..2; an ESCON2 digital inputs 1..4, high-speed digital inputs 1..4, digital outputs 1..2,
/// a high-speed digital output 1, analog inputs and outputs 1..2).
core::Result<SignalEnd> parse_signal_end(std::string_view text);

/// The end as the network file writes it (`node 3 digital input 5`, `%QX0.3`).
std::string to_string(const SignalEnd& end);

/// Why a wire cannot be: its source is not an output or its sink not an input, or one is
/// digital and the other analog; none if it can.
std::optional<std::string> wire_problem(const SignalWire& wire);

} // namespace eposp::device
