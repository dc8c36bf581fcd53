#include "eposp/canopen/lss_protocol.hpp"

#include <algorithm>
#include <cassert>
#include <fmt/format.h>

namespace eposp::canopen {

std::string_view to_string(LssCommand cs) {
    switch (cs) {
    case LssCommand::SwitchStateGlobal:
        return "switch state global";
    case LssCommand::ConfigureNodeId:
        return "configure node-ID";
    case LssCommand::ConfigureBitTiming:
        return "configure bit timing parameters";
    case LssCommand::ActivateBitTiming:
        return "activate bit timing parameters";
    case LssCommand::StoreConfiguration:
        return "store configuration";
    case LssCommand::SwitchStateSelectiveVendorId:
    case LssCommand::SwitchStateSelectiveProductCode:
    case LssCommand::SwitchStateSelectiveRevisionNumber:
    case LssCommand::SwitchStateSelectiveSerialNumber:
    case LssCommand::SwitchStateSelectiveResponse:
        return "switch state selective";
    case LssCommand::IdentifyRemoteSlaveVendorId:
    case LssCommand::IdentifyRemoteSlaveProductCode:
    case LssCommand::IdentifyRemoteSlaveRevisionLow:
    case LssCommand::IdentifyRemoteSlaveRevisionHigh:
    case LssCommand::IdentifyRemoteSlaveSerialLow:
    case LssCommand::IdentifyRemoteSlaveSerialHigh:
    case LssCommand::IdentifySlave:
        return "identify remote slave";
    case LssCommand::IdentifyNonConfiguredRemoteSlave:
    case LssCommand::IdentifyNonConfiguredSlave:
        return "identify non-configured remote slave";
    case LssCommand::Fastscan:
        return "fastscan";
    case LssCommand::InquireVendorId:
        return "inquire identity vendor-ID";
    case LssCommand::InquireProductCode:
        return "inquire identity product code";
    case LssCommand::InquireRevisionNumber:
        return "inquire identity revision number";
    case LssCommand::InquireSerialNumber:
        return "inquire identity serial number";
    case LssCommand::InquireNodeId:
        return "inquire node-ID";
    }
    return "unknown LSS command";
}

std::uint32_t LssAddress::part(LssPart which) const {
    switch (which) {
    case LssPart::VendorId:
        return vendor_id;
    case LssPart::ProductCode:
        return product_code;
    case LssPart::RevisionNumber:
        return revision_number;
    case LssPart::SerialNumber:
        return serial_number;
    }
    return 0;
}

void LssAddress::set_part(LssPart which, std::uint32_t value) {
    switch (which) {
    case LssPart::VendorId:
        vendor_id = value;
        break;
    case LssPart::ProductCode:
        product_code = value;
        break;
    case LssPart::RevisionNumber:
        revision_number = value;
        break;
    case LssPart::SerialNumber:
        serial_number = value;
        break;
    }
}

std::string_view to_string(LssPart part) {
    switch (part) {
    case LssPart::VendorId:
        return "vendor-ID";
    case LssPart::ProductCode:
        return "product code";
    case LssPart::RevisionNumber:
        return "revision number";
    case LssPart::SerialNumber:
        return "serial number";
    }
    return "unknown LSS address part";
}

std::string to_string(const LssAddress& address) {
    return fmt::format(
        "vendor-ID 0x{:08X}, product code 0x{:08X}, revision number 0x{:08X}, serial number "
        "0x{:08X}",
        address.vendor_id, address.product_code, address.revision_number, address.serial_number);
}

bool is_configured_node_id(NodeId id) {
    return id >= 1 && id <= 127;
}

bool is_lss_node_id(NodeId id) {
    return is_configured_node_id(id) || id == kLssUnconfiguredNodeId;
}

std::optional<std::uint32_t> lss_bit_rate(std::uint8_t table_selector, std::uint8_t table_index) {
    if (table_selector != kLssStandardBitTimingTable || table_index >= kLssBitTimingTable.size() ||
        kLssBitTimingTable[table_index] == 0) {
        return std::nullopt;
    }
    return kLssBitTimingTable[table_index];
}

std::optional<std::uint8_t> lss_bit_timing_index(std::uint32_t bit_rate) {
    const auto* found = std::find(kLssBitTimingTable.begin(), kLssBitTimingTable.end(), bit_rate);
    if (bit_rate == 0 || found == kLssBitTimingTable.end()) {
        return std::nullopt;
    }
    return static_cast<std::uint8_t>(found - kLssBitTimingTable.begin());
}

can::Frame lss_frame(std::uint32_t cob_id, LssCommand cs,
                     std::initializer_list<std::uint8_t> bytes) {
    assert(bytes.size() < can::kMaxDataLength);
    can::Frame frame;
    frame.id = cob_id;
    frame.dlc = can::kMaxDataLength;
    frame.data[0] = static_cast<std::uint8_t>(cs);
    std::copy(bytes.begin(), bytes.end(), frame.data.begin() + 1);
    return frame;
}

can::Frame lss_frame_u32(std::uint32_t cob_id, LssCommand cs, std::uint32_t value) {
    return lss_frame(cob_id, cs,
                     {static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(value >> 8),
                      static_cast<std::uint8_t>(value >> 16),
                      static_cast<std::uint8_t>(value >> 24)});
}

can::Frame lss_fastscan_frame(const FastscanRequest& request) {
    can::Frame frame = lss_frame_u32(kLssMasterCobId, LssCommand::Fastscan, request.id_number);
    frame.data[5] = request.bit_checked;
    frame.data[6] = static_cast<std::uint8_t>(request.sub);
    frame.data[7] = static_cast<std::uint8_t>(request.next);
    return frame;
}

std::optional<LssCommand> lss_command(const can::Frame& frame, std::uint32_t cob_id) {
    if (frame.id != cob_id || frame.extended || frame.remote || frame.error ||
        frame.dlc != can::kMaxDataLength) {
        return std::nullopt;
    }
    return static_cast<LssCommand>(frame.data[0]);
}

std::uint32_t lss_u32(const can::Frame& frame) {
    return static_cast<std::uint32_t>(frame.data[1]) |
           static_cast<std::uint32_t>(frame.data[2]) << 8 |
           static_cast<std::uint32_t>(frame.data[3]) << 16 |
           static_cast<std::uint32_t>(frame.data[4]) << 24;
}

std::uint16_t lss_u16(const can::Frame& frame) {
    return static_cast<std::uint16_t>(frame.data[1] | frame.data[2] << 8);
}

std::optional<FastscanRequest> lss_fastscan_request(const can::Frame& frame) {
    const std::uint8_t bit_checked = frame.data[5];
    const std::uint8_t sub = frame.data[6];
    const std::uint8_t next = frame.data[7];
    if ((bit_checked > 31 && bit_checked != kFastscanConfirm) || sub >= kLssPartCount ||
        next >= kLssPartCount) {
        return std::nullopt;
    }
    return FastscanRequest{lss_u32(frame), bit_checked, static_cast<LssPart>(sub),
                           static_cast<LssPart>(next)};
}

} // namespace eposp::canopen
