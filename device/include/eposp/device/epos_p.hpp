#pragma once

#include "eposp/can/virtual_bus.hpp"
#include "eposp/core/event_loop.hpp"
#include "eposp/device/axis_trace.hpp"
#include "eposp/device/epos_p_dictionary.hpp"
#include "eposp/device/fault_injector.hpp"
#include "eposp/device/network_file.hpp"
#include "eposp/device/plc.hpp"
#include "eposp/drives/epos2/epos2_drive.hpp"
#include "eposp/drives/escon2/escon2_drive.hpp"
#include "eposp/manager/network_boot.hpp"
#include "eposp/plcopen/motion_library.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace eposp::device {

class DeviceAxisLink;
class EventTasks;
class ManufacturerStatus;
class NetworkPort;
class ProgramStore;
class SeverablePort;
class SignalWires;

struct EposPConfig {
    /// Virtual time (as fast as the CPU allows, deterministic) or the wall clock.
    core::Pace pace = core::Pace::Virtual;
    vm::RuntimeConfig runtime;
    /// The internal EPOS2 on port 1; its node-ID is always 1 (DESIGN.md, "CAN").
    drives::epos2::Epos2DriveConfig internal_drive;
    /// Port 2, the external CAN bus, and 0x5001's default; a bit rate stored with "save" takes
    /// its place at power-up (10.32).
    std::uint32_t external_bit_rate = 1'000'000;
    /// The controller's node-ID on port 2 (0x5000) and serial number (0x1018 sub 4).
    canopen::NodeId node_id = 1;
    std::uint32_t serial_number = 0;
    /// The non-volatile memory of 0x1010 / 0x1011, applied at power-up; empty: "save" is
    /// refused.
    std::filesystem::path parameter_file;
    /// The program memory behind 0x1F50 (CiA 302-3 program download), loaded at power-up;
    /// empty: a downloaded program lives in memory only.
    std::filesystem::path program_file;
};

/// The EPOS P: the PLC, its object dictionary and two CAN ports on one event loop. Port 1 is the
/// internal bus to the internal EPOS2 (node 1, always present); port 2 is the external CAN bus,
/// an in-process virtual bus that simulated slaves join. The dictionary is bound to the PLC
/// (program control 0x5F51, the process image 0xA000 - 0xA680, the PLC's errors in 0x1003; see
/// plc_objects.hpp). Powered up by the constructor: the stored parameters and the stored program
/// are loaded, the internal EPOS2 boots at once; a program runs once it is loaded (downloaded to
/// 0x1F50, or plc().load()) and started (by 0x5F51, 0x1F51, start_stored_program() or
/// plc().runtime().start()). Destroying it is a power-down: a running program is stopped, which
/// saves its RETAIN variables.
///
/// While the EPOS P produces SYNC, each cyclic task whose interval is a multiple of the SYNC
/// period runs in step with it: the synchronous window 0x1007 after the SYNC (half a period
/// without a window), once the slaves' synchronous TPDOs of that SYNC are in. Its outputs go
/// out with the synchronous TPDOs of the next SYNC.
///
/// Neither copyable nor movable: the drive, the ports and the PLC refer to the loop.
class EposP {
public:
    EposP();
    explicit EposP(EposPConfig config);
    ~EposP();
    EposP(const EposP&) = delete;
    EposP& operator=(const EposP&) = delete;

    core::EventLoop& loop() { return loop_; }
    Plc& plc() { return plc_; }
    /// The motion blocks' axes (the axis table 0x5280 - 0x529F) as the PLC drives them.
    const plcopen::MotionLibrary& motion() const { return *motion_; }
    canopen::ObjectDictionary& objects() { return dictionary_.objects(); }

    /// Sets the network up as the file says (apply_network) and powers up an in-process EPOS2 on
    /// port 2 for each slave of kind epos2 (serial number = its node-ID).
    void add_network(const NetworkFile& network);
    /// The simulated EPOS2s add_network() put on port 2.
    const std::vector<std::unique_ptr<drives::epos2::Epos2Drive>>& simulated_slaves() const {
        return slaves_;
    }
    /// The ESCON2 the network file names `name`; none if it names none.
    drives::escon2::Escon2Drive* escon2(const std::string& name);

    /// Lets `event` release the event task it names (docs/network.md, "Events"); the program
    /// must be loaded. The error says why not: no such task, or not an event task.
    std::optional<core::Error> bind_event(const EventBinding& event);

    /// The axes of the axis table (0x5280 + n sub 1) that a drive in this process serves: the
    /// internal EPOS2 and the simulated slaves of add_network(), in axis order.
    std::vector<TracedAxis> simulated_axes() const;

    /// Starts the loaded program as 0x5F51 does (1 cold, 2 warm, 3 hot); a cold or warm start
    /// boots the networks too (8.1). The error says why it cannot start.
    std::optional<core::Error> start_program(vm::StartMode mode);
    /// 10.37: starts the stored program as the stored 0x5F51 says (0 leaves it stopped; 1 cold,
    /// 2 warm, 3 hot), once the device is set up (its network added); the networks boot with
    /// it, at a hot start too (a power-up). The error says why it cannot start; without a stored
    /// program nothing happens (the owner boots the networks).
    std::optional<core::Error> start_stored_program();
    /// Why the last download (0x1F50) or the power-up's load of the stored program was refused
    /// (0x1F57 says which way); empty after a success.
    const std::string& program_refusal() const;
    /// Boots the networks of both ports as the dictionary's network lists say (8.1): the
    /// internal EPOS2 (sub-index 128 of 0x1F81 ...) on port 1, the slaves of sub-indices 1..127
    /// on port 2. Failures go to the error history with their port and node-ID.
    void boot_networks();
    /// The network list the boot of port 1 or 2 works from now: the dictionary's objects and
    /// the configuration writes of each slave (its concise DCF).
    manager::NetworkList network_list(std::uint8_t port) const;
    /// The boot-up of port 1 (kInternalPort) or 2 (kExternalPort).
    const manager::NetworkBoot& network(std::uint8_t port) const;

    /// Port 1: the internal bus, the controller's own port on it and the internal EPOS2.
    can::VirtualBus& internal_bus() { return internal_bus_; }
    can::Port& internal_port() { return *internal_port_; }
    drives::epos2::Epos2Drive& internal_drive() { return *internal_drive_; }
    /// Port 2: the external CAN bus and the controller's own port on it.
    can::VirtualBus& external_bus() { return external_bus_; }
    can::Port& external_port() { return *external_port_; }

    /// Faults injected into the simulated network: a silent slave, a limit switch, a drive
    /// error, damaged PDOs (docs/eposp.md, "Fault injection").
    FaultInjector& faults() { return *faults_; }

    /// The manager of port 1 or 2 (a type of the device's own sources: for the service
    /// interface, which reaches the ports' nodes through it).
    NetworkPort& network_port(std::uint8_t port);

private:
    friend class FaultInjector; // reaches the simulated EPOS2s and their cables

    void load_stored_parameters(const std::filesystem::path& file);
    /// 10.32: port 2 restarts at the bit rate 0x5001 holds after the stored parameters.
    void apply_can_bit_rate();
    /// DESIGN.md, "One communication cycle": at each SYNC, puts the PLC's cyclic tasks a
    /// fixed delay after it, when the slaves' synchronous TPDOs are in.
    void follow_sync();
    /// The simulated EPOS2 with `node` on `port` (the internal one on port 1).
    drives::epos2::Epos2Drive& simulated_drive(std::uint8_t port, canopen::NodeId node);
    drives::escon2::Escon2Drive& simulated_escon2(const std::string& name);

    core::EventLoop loop_;
    can::VirtualBus internal_bus_;
    std::unique_ptr<can::VirtualPort> internal_port_;
    std::unique_ptr<can::VirtualPort> internal_drive_port_;
    std::unique_ptr<SeverablePort> internal_drive_link_; ///< the drive's cable to its bus
    std::unique_ptr<drives::epos2::Epos2Drive> internal_drive_;
    can::VirtualBus external_bus_;
    std::unique_ptr<can::VirtualPort> external_port_;
    Plc plc_;
    EposPDictionary dictionary_;
    std::unique_ptr<NetworkPort> internal_network_;
    std::unique_ptr<NetworkPort> external_network_;
    std::unique_ptr<DeviceAxisLink> axis_link_;
    std::unique_ptr<plcopen::MotionLibrary> motion_; ///< its blocks are natives of plc_
    std::unique_ptr<ManufacturerStatus> manufacturer_status_;
    std::unique_ptr<EventTasks> event_tasks_; ///< plc_ asks it at each load
    std::unique_ptr<ProgramStore> program_store_;
    std::uint16_t stored_program_control_ = 0; ///< 0x5F51 as stored: the boot-up state
    std::vector<std::unique_ptr<can::VirtualPort>> slave_ports_;
    std::vector<std::unique_ptr<SeverablePort>> slave_links_; ///< each slave's cable to the bus
    std::vector<std::unique_ptr<drives::epos2::Epos2Drive>> slaves_;
    /// The network files' ESCON2s by name (no CAN: the wires reach them).
    std::vector<std::pair<std::string, std::unique_ptr<drives::escon2::Escon2Drive>>> escon2s_;
    std::unique_ptr<SignalWires> wires_; ///< the network files' wires between the devices
    std::unique_ptr<FaultInjector> faults_;
};

} // namespace eposp::device
