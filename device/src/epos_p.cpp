#include "eposp/device/epos_p.hpp"

namespace eposp::device {
namespace {

constexpr canopen::NodeId kInternalDriveNodeId = 1;

drives::epos2::Epos2DriveConfig internal_drive_config(drives::epos2::Epos2DriveConfig config) {
    config.dictionary.node_id = kInternalDriveNodeId;
    return config;
}

} // namespace

EposP::EposP(EposPConfig config)
    : loop_(config.pace), internal_bus_(loop_, can::BusConfig{.name = "internal"}),
      internal_port_(internal_bus_.connect("epos-p")),
      internal_drive_port_(internal_bus_.connect("internal-epos2")),
      internal_drive_(std::make_unique<drives::epos2::Epos2Drive>(
          loop_, *internal_drive_port_, internal_drive_config(std::move(config.internal_drive)))),
      external_bus_(loop_,
                    can::BusConfig{.name = "external", .bitrate = config.external_bit_rate}),
      external_port_(external_bus_.connect("epos-p")), plc_(loop_, std::move(config.runtime)) {
    internal_drive_->start();
}

EposP::~EposP() = default;

} // namespace eposp::device
