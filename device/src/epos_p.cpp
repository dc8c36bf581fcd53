#include "eposp/device/epos_p.hpp"

#include "device_axis_link.hpp"
#include "eposp/device/axis_process_data.hpp"
#include "eposp/device/error_entry.hpp"
#include "eposp/device/escon2_machine.hpp"
#include "event_tasks.hpp"
#include "manufacturer_status.hpp"
#include "network_port.hpp"
#include "plc_objects.hpp"
#include "program_download.hpp"
#include "program_store.hpp"
#include "severable_port.hpp"
#include "signal_wires.hpp"
#include "variable_access.hpp"

#include <fmt/format.h>

namespace eposp::device {
namespace {

constexpr canopen::NodeId kInternalDriveNodeId = 1;

drives::epos2::Epos2DriveConfig internal_drive_config(drives::epos2::Epos2DriveConfig config) {
    config.dictionary.node_id = kInternalDriveNodeId;
    return config;
}

EposPDictionaryConfig dictionary_config(const EposPConfig& config, const Plc& plc,
                                        std::function<canopen::AbortCode()> erase_program) {
    EposPDictionaryConfig dictionary;
    dictionary.node_id = config.node_id;
    dictionary.can_bit_rate = config.external_bit_rate;
    dictionary.serial_number = config.serial_number;
    dictionary.parameter_file = config.parameter_file;
    dictionary.restore.restore_permitted = [&plc] {
        return restore_permitted(plc);
    };
    dictionary.erase_program = std::move(erase_program);
    return dictionary;
}

} // namespace

EposP::EposP() : EposP(EposPConfig{}) {}

EposP::EposP(EposPConfig config)
    : loop_(config.pace), internal_bus_(loop_, can::BusConfig{.name = "internal"}),
      internal_port_(internal_bus_.connect("epos-p")),
      internal_drive_port_(internal_bus_.connect("internal-epos2")),
      internal_drive_link_(std::make_unique<SeverablePort>(*internal_drive_port_)),
      internal_drive_(std::make_unique<drives::epos2::Epos2Drive>(
          loop_, *internal_drive_link_, internal_drive_config(std::move(config.internal_drive)))),
      external_bus_(loop_, can::BusConfig{.name = "external", .bitrate = config.external_bit_rate}),
      external_port_(external_bus_.connect("epos-p")), plc_(loop_, std::move(config.runtime)),
      dictionary_(dictionary_config(config, plc_, [this] { return program_store_->clear(); })) {
    load_stored_parameters(config.parameter_file);
    apply_can_bit_rate();
    const auto start = [this](vm::StartMode mode) {
        return start_program(mode);
    };
    bind_plc(dictionary_.objects(), plc_, start);
    program_store_ =
        std::make_unique<ProgramStore>(dictionary_.objects(), plc_, std::move(config.program_file));
    bind_program_download(dictionary_.objects(), *program_store_, plc_, start);
    bind_variable_access(dictionary_.objects(), plc_);
    internal_network_ =
        std::make_unique<NetworkPort>(loop_, *internal_port_, dictionary_.objects(), kInternalPort);
    external_network_ =
        std::make_unique<NetworkPort>(loop_, *external_port_, dictionary_.objects(), kExternalPort);
    for (auto [port, network] : {std::pair{internal_port_.get(), internal_network_.get()},
                                 std::pair{external_port_.get(), external_network_.get()}}) {
        // An init-capture: clang 14 cannot capture a structured binding.
        port->on_overflow([lossy = network](can::Overflow overflow, const can::Frame&) {
            if (overflow == can::Overflow::Receive) {
                lossy->report_lost_frame();
            }
        });
    }
    internal_network_->on_sync([this] { follow_sync(); });
    axis_link_ = std::make_unique<DeviceAxisLink>(
        dictionary_.objects(), plc_.runtime().process_image(),
        [this](std::uint8_t port) -> NetworkPort& { return network_port(port); });
    motion_ = std::make_unique<plcopen::MotionLibrary>(*axis_link_);
    motion_->register_blocks(plc_.natives());
    manufacturer_status_ = std::make_unique<ManufacturerStatus>(dictionary_.objects());
    for (const std::uint8_t port : {kInternalPort, kExternalPort}) {
        network_port(port).on_emergency([this, port](const canopen::Emergency& emergency) {
            manufacturer_status_->on_emergency(port, emergency);
        });
    }
    event_tasks_ = std::make_unique<EventTasks>(
        plc_.runtime(), dictionary_.objects(),
        [this](std::uint8_t port) -> NetworkPort& { return network_port(port); });
    plc_.observe_loads(*event_tasks_);
    program_store_->power_up(); // after the motion blocks: a program may call them
    wires_ = std::make_unique<SignalWires>(
        loop_, dictionary_.objects(), plc_.runtime().process_image(),
        SignalWires::Drives{
            .epos2 = [this](std::uint8_t port, canopen::NodeId node) -> drives::epos2::Epos2Drive& {
                return simulated_drive(port, node);
            },
            .escon2 = [this](const std::string& name) -> drives::escon2::Escon2Drive& {
                return simulated_escon2(name);
            }});
    faults_ = std::make_unique<FaultInjector>(*this);
    internal_drive_->start();
}

// At power-up, before anything reads the dictionary: the values 0x1010 "save" stored.
void EposP::load_stored_parameters(const std::filesystem::path& file) {
    if (!file.empty() && dictionary_.store().load_stored_values().refused()) {
        record_error(dictionary_.objects(),
                     {.code = kEepromError, .port = 0, .node = 0, .warning = false});
    }
    stored_program_control_ =
        canopen::decode<std::uint16_t>(dictionary_.objects().find(kProgramControlIndex, 0)->value);
}

void EposP::apply_can_bit_rate() {
    const auto code = dictionary_.objects().get_as<std::uint16_t>(kCanBitRateIndex, 0);
    // The default stands for the configured rate (which table 28 may not list); automatic
    // detection finds the rate the bus has.
    if (code == canopen::decode<std::uint16_t>(
                    dictionary_.objects().find(kCanBitRateIndex, 0)->default_value)) {
        return;
    }
    if (const auto rate = can_bit_rate_of(code)) {
        external_bus_.set_bitrate(*rate);
    }
}

std::optional<core::Error> EposP::bind_event(const EventBinding& event) {
    return event_tasks_->bind(event);
}

void EposP::follow_sync() {
    const canopen::ObjectDictionary& od = dictionary_.objects();
    const auto period = std::chrono::microseconds(od.get_as<std::uint32_t>(0x1006, 0));
    const auto window = std::chrono::microseconds(od.get_as<std::uint32_t>(0x1007, 0));
    const core::Duration delay =
        window.count() > 0 && window < period ? core::Duration(window) : core::Duration(period) / 2;
    plc_.runtime().align_cycles(loop_.now() + delay, period);
    // What the axes run goes on when no block of theirs is called: with the TPDOs in, as the
    // tasks of the cycle see them (DESIGN.md, "One communication cycle").
    loop_.after(delay, [this] { motion_->poll(); });
    event_tasks_->on_sync();
}

NetworkPort& EposP::network_port(std::uint8_t port) {
    return *(port == kInternalPort ? internal_network_ : external_network_);
}

void EposP::add_network(const NetworkFile& network) {
    apply_network(network, dictionary_.objects());
    for (const NetworkSlave& slave : network.slaves) {
        if (slave.concise_dcf) {
            network_port(slave.port).set_slave_configuration(slave.node_id, *slave.concise_dcf);
        } else if (slave.axis) {
            network_port(slave.port)
                .set_slave_configuration(slave.node_id, axis_slave_configuration(slave.node_id));
        }
        if (slave.port != kExternalPort || slave.kind != NetworkSlave::Kind::Epos2) {
            continue;
        }
        drives::epos2::Epos2DriveConfig config;
        config.dictionary.node_id = slave.node_id;
        config.dictionary.serial_number = slave.node_id;
        // 0x200A (8.2.42): automatic bit rate detection finds the rate of the bus it joins.
        config.dictionary.bit_rate = external_bus_.config().bitrate;
        if (slave.plant) {
            config.axis = *slave.plant;
        }
        slave_ports_.push_back(external_bus_.connect(fmt::format("epos2-{}", slave.node_id)));
        slave_links_.push_back(std::make_unique<SeverablePort>(*slave_ports_.back()));
        slaves_.push_back(std::make_unique<drives::epos2::Epos2Drive>(loop_, *slave_links_.back(),
                                                                      std::move(config)));
        slaves_.back()->start();
    }
    for (const NetworkEscon2& escon2 : network.escon2s) {
        auto drive = start_escon2(loop_, escon2);
        if (!drive) {
            // The network file's reader wrote each parameter into a dictionary of the same
            // hardware, and this one has stored nothing.
            throw std::logic_error("ESCON2 " + escon2.name + ": " + drive.error());
        }
        escon2s_.emplace_back(escon2.name, std::move(*drive));
    }
    wires_->add(network.wires);
}

drives::escon2::Escon2Drive* EposP::escon2(const std::string& name) {
    for (auto& [drive_name, drive] : escon2s_) {
        if (drive_name == name) {
            return drive.get();
        }
    }
    return nullptr;
}

drives::escon2::Escon2Drive& EposP::simulated_escon2(const std::string& name) {
    if (drives::escon2::Escon2Drive* drive = escon2(name)) {
        return *drive;
    }
    // The network file's reader lets no wire name an ESCON2 it does not simulate.
    throw std::logic_error("no ESCON2 named " + name + " is simulated");
}

drives::epos2::Epos2Drive& EposP::simulated_drive(std::uint8_t port, canopen::NodeId node) {
    if (port == kInternalPort) {
        return *internal_drive_;
    }
    for (const auto& drive : slaves_) {
        if (drive->node().node_id() == node) {
            return *drive;
        }
    }
    // The network file's reader lets no wire name an EPOS2 it does not simulate.
    throw std::logic_error(
        fmt::format("no EPOS2 with node {} is simulated on port {}", node, port));
}

std::vector<TracedAxis> EposP::simulated_axes() const {
    std::vector<TracedAxis> axes;
    for (std::uint8_t axis = 0; axis < kAxisCount; ++axis) {
        const auto slave = dictionary_.objects().get_as<std::uint8_t>(
            static_cast<std::uint16_t>(kAxisIndex + axis), 1);
        const plcopen::AxisDriver* driver = &motion_->axis(axis);
        if (slave == kInternalSlave) {
            axes.push_back({axis, internal_drive_.get(), driver});
            continue;
        }
        for (const auto& drive : slaves_) {
            if (drive->node().node_id() == slave) {
                axes.push_back({axis, drive.get(), driver});
            }
        }
    }
    return axes;
}

std::optional<core::Error> EposP::start_program(vm::StartMode mode) {
    if (auto error = plc_.runtime().start(mode)) {
        return error;
    }
    program_store_->started();
    // 8.1: the boot-up runs at each cold or warm start of the application.
    if (mode != vm::StartMode::Hot) {
        boot_networks();
    }
    return std::nullopt;
}

std::optional<core::Error> EposP::start_stored_program() {
    if (!program_store_->has_program() ||
        stored_program_control_ == static_cast<std::uint16_t>(ProgramControl::Stopped)) {
        return std::nullopt;
    }
    const auto mode = static_cast<vm::StartMode>(stored_program_control_);
    if (auto error = start_program(mode)) {
        return error;
    }
    // Firmware 0102h: the networks boot at power-up; a hot start alone would leave them (8.1).
    if (mode == vm::StartMode::Hot) {
        boot_networks();
    }
    return std::nullopt;
}

const std::string& EposP::program_refusal() const {
    return program_store_->refusal();
}

void EposP::boot_networks() {
    internal_network_->boot();
    external_network_->boot();
}

manager::NetworkList EposP::network_list(std::uint8_t port) const {
    return (port == kInternalPort ? internal_network_ : external_network_)->list();
}

const manager::NetworkBoot& EposP::network(std::uint8_t port) const {
    return (port == kInternalPort ? internal_network_ : external_network_)->network();
}

// A power-down: the RETAIN variables are saved as a stop saves them (10.37: a warm start finds
// the values from before power down).
EposP::~EposP() {
    plc_.runtime().stop();
}

} // namespace eposp::device
