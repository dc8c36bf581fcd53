#include "eposp/device/epos_p.hpp"

#include "eposp/device/axis_process_data.hpp"
#include "network_port.hpp"
#include "plc_objects.hpp"

#include <fmt/format.h>

namespace eposp::device {
namespace {

constexpr canopen::NodeId kInternalDriveNodeId = 1;

drives::epos2::Epos2DriveConfig internal_drive_config(drives::epos2::Epos2DriveConfig config) {
    config.dictionary.node_id = kInternalDriveNodeId;
    return config;
}

EposPDictionaryConfig dictionary_config(const EposPConfig& config, const Plc& plc) {
    EposPDictionaryConfig dictionary;
    dictionary.node_id = config.node_id;
    dictionary.serial_number = config.serial_number;
    dictionary.parameter_file = config.parameter_file;
    dictionary.restore.restore_permitted = [&plc] {
        return restore_permitted(plc);
    };
    return dictionary;
}

} // namespace

EposP::EposP() : EposP(EposPConfig{}) {}

EposP::EposP(EposPConfig config)
    : loop_(config.pace), internal_bus_(loop_, can::BusConfig{.name = "internal"}),
      internal_port_(internal_bus_.connect("epos-p")),
      internal_drive_port_(internal_bus_.connect("internal-epos2")),
      internal_drive_(std::make_unique<drives::epos2::Epos2Drive>(
          loop_, *internal_drive_port_, internal_drive_config(std::move(config.internal_drive)))),
      external_bus_(loop_, can::BusConfig{.name = "external", .bitrate = config.external_bit_rate}),
      external_port_(external_bus_.connect("epos-p")), plc_(loop_, std::move(config.runtime)),
      dictionary_(dictionary_config(config, plc_)) {
    bind_plc(dictionary_.objects(), plc_,
             [this](vm::StartMode mode) { return start_program(mode); });
    internal_network_ =
        std::make_unique<NetworkPort>(loop_, *internal_port_, dictionary_.objects(), kInternalPort);
    external_network_ =
        std::make_unique<NetworkPort>(loop_, *external_port_, dictionary_.objects(), kExternalPort);
    for (auto [port, network] : {std::pair{internal_port_.get(), internal_network_.get()},
                                 std::pair{external_port_.get(), external_network_.get()}}) {
        port->on_overflow([network](can::Overflow overflow, const can::Frame&) {
            if (overflow == can::Overflow::Receive) {
                network->report_lost_frame();
            }
        });
    }
    internal_network_->on_sync([this] { follow_sync(); });
    internal_drive_->start();
}

void EposP::follow_sync() {
    const canopen::ObjectDictionary& od = dictionary_.objects();
    const auto period = std::chrono::microseconds(od.get_as<std::uint32_t>(0x1006, 0));
    const auto window = std::chrono::microseconds(od.get_as<std::uint32_t>(0x1007, 0));
    const core::Duration delay =
        window.count() > 0 && window < period ? core::Duration(window) : core::Duration(period) / 2;
    plc_.runtime().align_cycles(loop_.now() + delay, period);
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
                .set_slave_configuration(slave.node_id,
                                         axis_slave_configuration(slave.node_id, *slave.axis));
        }
        if (slave.port != kExternalPort || slave.kind != NetworkSlave::Kind::Epos2) {
            continue;
        }
        drives::epos2::Epos2DriveConfig config;
        config.dictionary.node_id = slave.node_id;
        config.dictionary.serial_number = slave.node_id;
        slave_ports_.push_back(external_bus_.connect(fmt::format("epos2-{}", slave.node_id)));
        slaves_.push_back(std::make_unique<drives::epos2::Epos2Drive>(loop_, *slave_ports_.back(),
                                                                      std::move(config)));
        slaves_.back()->start();
    }
}

std::vector<TracedAxis> EposP::simulated_axes() const {
    std::vector<TracedAxis> axes;
    for (std::uint8_t axis = 0; axis < kAxisCount; ++axis) {
        const auto slave =
            dictionary_.objects().get_as<std::uint8_t>(static_cast<std::uint16_t>(kAxisIndex + axis), 1);
        if (slave == kInternalSlave) {
            axes.push_back({axis, internal_drive_.get()});
            continue;
        }
        for (const auto& drive : slaves_) {
            if (drive->node().node_id() == slave) {
                axes.push_back({axis, drive.get()});
            }
        }
    }
    return axes;
}

std::optional<core::Error> EposP::start_program(vm::StartMode mode) {
    if (auto error = plc_.runtime().start(mode)) {
        return error;
    }
    // 8.1: the boot-up runs at each cold or warm start of the application.
    if (mode != vm::StartMode::Hot) {
        boot_networks();
    }
    return std::nullopt;
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

EposP::~EposP() = default;

} // namespace eposp::device
