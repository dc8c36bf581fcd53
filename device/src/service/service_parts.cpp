#include "service_parts.hpp"

#include "eposp/device/epos_p.hpp"
#include "eposp/drives/escon2/escon2_drive.hpp"
#include "eposp/service/commands.hpp"

namespace eposp::device {
namespace {

constexpr std::uint16_t kFrameTimeoutIndex = 0x5005; // EPOS P firmware specification 10.35

// The EPOS2 communication guide's codes, which the EPOS P answers.
constexpr ServiceDialect kEposPDialect{
    .unknown_command = service::error::kIllegalCommand,
    .wrong_node = service::error::kWrongNodeId,
    .segmented_expected = static_cast<std::uint32_t>(canopen::AbortCode::LengthTooHigh),
    .answers_crc_errors = false,
};

// ESCON2 FW spec 7.2, table 111: "command unknown", "segmented transfer expected" and "CRC
// error" are there; a node the ESCON2 does not reach (it has none but itself) is a parameter
// out of range (decided here: the table names no wrong node-ID).
constexpr ServiceDialect kEscon2Dialect{
    .unknown_command = static_cast<std::uint32_t>(canopen::AbortCode::CommandSpecifier),
    .wrong_node = static_cast<std::uint32_t>(canopen::AbortCode::InvalidValue),
    .segmented_expected = service::error::kSegmentedTransferExpected,
    .answers_crc_errors = true,
};

// The ESCON2 has no object for it: the EPOS P's default 0x5005 (decided here).
constexpr core::Duration kEscon2FrameTimeout = std::chrono::milliseconds(500);

} // namespace

ServiceParts service_parts(EposP& device) {
    return ServiceParts{.objects = device.objects(),
                        .dialect = kEposPDialect,
                        .frame_timeout =
                            [&device] {
                                return core::Duration(std::chrono::milliseconds(
                                    device.objects().get_as<std::uint16_t>(kFrameTimeoutIndex, 0)));
                            },
                        .network_port = [&device](std::uint8_t port) -> NetworkPort& {
                            return device.network_port(port);
                        }};
}

ServiceParts service_parts(drives::escon2::Escon2Drive& drive) {
    return ServiceParts{.objects = drive.objects(),
                        .dialect = kEscon2Dialect,
                        .frame_timeout = [] { return kEscon2FrameTimeout; },
                        .network_port = {}};
}

} // namespace eposp::device
