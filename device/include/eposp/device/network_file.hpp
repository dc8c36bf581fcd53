#pragma once

#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/object_dictionary.hpp"
#include "eposp/core/result.hpp"
#include "eposp/core/time.hpp"
#include "eposp/device/escon2_machine.hpp"
#include "eposp/device/event_binding.hpp"
#include "eposp/device/signal_wire.hpp"
#include "eposp/drives/escon2/escon2_hardware.hpp"
#include "eposp/drives/plant/servo_axis.hpp"
#include "eposp/manager/network_list.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::device {

/// One slave of a network file (docs/network.md).
struct NetworkSlave {
    enum class Kind : std::uint8_t {
        Epos2,    ///< simulated in this process
        External, ///< another process on socketcand, or real hardware
    };
    std::uint8_t port = 2; ///< 1: the internal EPOS2 (node 1), 2: the CAN bus
    canopen::NodeId node_id = 0;
    Kind kind = Kind::Epos2;
    bool mandatory = true;
    std::optional<std::uint8_t> axis; ///< 0..31: the axis it serves (0x5280 + axis)
    /// Expected values of the boot-up checks; 0 is not checked.
    std::uint32_t device_type = 0;
    canopen::LssAddress identity;
    /// 0x1F26 / 0x1F27, against the slave's 0x1020 (checked when both are set).
    std::uint32_t configuration_date = 0;
    std::uint32_t configuration_time = 0;
    /// The writes of the concise DCF the file names, instead of the axis' PDO set-up.
    std::optional<std::vector<manager::ConfigurationWrite>> concise_dcf;
    /// The consumer heartbeat time the controller watches it with; 0: no supervision.
    std::uint16_t heartbeat_ms = 100;
    /// A simulated slave's machine: motor, load, switches … (an axis file, as `eposp drive
    /// epos2 --config` reads); the reference axis without one.
    std::optional<drives::plant::AxisParameters> plant;
};

/// An ESCON2 simulated in this process (docs/network.md, "ESCON2 servo controllers"): it has no
/// CAN, the machine reaches it through wires to its pins.
struct NetworkEscon2 : Escon2Machine {
    std::string name; ///< what the wires call it
};

/// What a user writes instead of setting objects one by one.
struct NetworkFile {
    canopen::NodeId node_id = 1;                               ///< the EPOS P's on port 2 (0x5000)
    std::uint32_t bit_rate = 1'000'000;                        ///< port 2, bit/s
    core::Duration boot_time = std::chrono::milliseconds(500); ///< 0x1F89
    /// 0x1006 with the generate bit of 0x1005; none: no SYNC.
    std::optional<core::Duration> sync_period;
    std::vector<NetworkSlave> slaves;
    std::vector<EventBinding> events;
    std::vector<NetworkEscon2> escon2s;
    /// Outputs wired to inputs: of the simulated drives, of the process image.
    std::vector<SignalWire> wires;
};

/// Reads a network file; every mistake is an error "file:line:col: error: message" (`source`
/// names the text): unknown keys, values out of range, a node listed twice on a port, an axis
/// served twice, an internal slave other than node 1, a slave with the EPOS P's own node-ID, a
/// wire to or from a drive the file does not simulate, an input wired twice, an ESCON2 parameter
/// the device refuses.
/// A slave's `dcf` is read from `base` / its name (a file's directory).
core::Result<NetworkFile> parse_network_file(std::string_view text, std::string_view source,
                                             const std::filesystem::path& base = {});
core::Result<NetworkFile> load_network_file(const std::filesystem::path& path);

/// Writes the network into the EPOS P's dictionary: per slave 0x1F81 (slave, boot slave,
/// mandatory), 0x1F84 - 0x1F88, 0x1F26 / 0x1F27, 0x1016 (port code, node-ID, time) and its axis'
/// slave number 0x5280 + axis sub 1 (table 30); 0x1F89; a SYNC period in 0x1006 and the generate
/// bit of 0x1005. Axes the file does not name keep their defaults.
void apply_network(const NetworkFile& network, canopen::ObjectDictionary& od);

} // namespace eposp::device
