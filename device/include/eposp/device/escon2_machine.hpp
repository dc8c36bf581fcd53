#pragma once

#include "eposp/canopen/value_codec.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/core/result.hpp"
#include "eposp/drives/escon2/escon2_drive.hpp"
#include "eposp/drives/escon2/escon2_hardware.hpp"
#include "eposp/drives/plant/servo_axis.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace eposp::device {

/// What a simulated ESCON2 is: its hardware, the machine it drives and the parameters it keeps
/// in its memory (docs/network.md, "ESCON2 servo controllers"). The network file's `escon2`
/// entries hold one each; `eposp drive escon2 --config` reads one from a file of its own.
struct Escon2Machine {
    /// One object written at power-up, as a configuration tool's download over USB writes it.
    struct Parameter {
        std::uint16_t index = 0;
        std::uint8_t sub_index = 0;
        canopen::Bytes value;
    };
    drives::escon2::Escon2Hardware hardware = drives::escon2::Escon2Hardware::Module60_30;
    /// Its machine (an axis file); the reference axis without one.
    std::optional<drives::plant::AxisParameters> plant;
    std::vector<Parameter> parameters; ///< in the file's order, each checked as the device would
};

/// Reads the machine file of `eposp drive escon2 --config`: the keys `hardware`, `plant`
/// (relative to `base`) and `parameters` of a network file's `escon2` entry, without its name;
/// every mistake is an error "file:line:col: error: message" (`source` names the text).
core::Result<Escon2Machine> parse_escon2_machine(std::string_view text, std::string_view source,
                                                 const std::filesystem::path& base = {});
core::Result<Escon2Machine> load_escon2_machine(const std::filesystem::path& path);

/// A simulated ESCON2 of `machine` on `loop`, powered up (`Escon2Drive::start`: the values its
/// parameter file stored), then the machine's parameters written in order, as a configuration
/// tool downloads them. `dictionary` gives the rest of its set-up; its hardware is the
/// machine's. The error names a parameter the device refuses after its stored values (one
/// functionality on two pins ...).
core::Result<std::unique_ptr<drives::escon2::Escon2Drive>>
start_escon2(core::EventLoop& loop, const Escon2Machine& machine,
             drives::escon2::Escon2DictionaryConfig dictionary = {});

} // namespace eposp::device
