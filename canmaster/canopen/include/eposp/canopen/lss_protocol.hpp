#pragma once

#include "eposp/can/frame.hpp"
#include "eposp/canopen/nmt_state.hpp"

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace eposp::canopen {

// Layer setting services, CiA 305 (EPOS2 FW spec 7.4): the identifiers, command specifiers and
// frame layouts that the LSS slave and master share. Every LSS frame has 8 data bytes, the
// command specifier in byte 0, numbers little-endian from byte 1, reserved bytes 0.

/// EPOS2 FW spec 7.4: LSS master message, master → slaves.
inline constexpr std::uint32_t kLssMasterCobId = 0x7E5;
/// EPOS2 FW spec 7.4: LSS slave message, slave → master.
inline constexpr std::uint32_t kLssSlaveCobId = 0x7E4;

/// The command specifiers of CiA 305 (EPOS2 FW spec 7.4.1, table 7-66), requests and responses.
enum class LssCommand : std::uint8_t {
    SwitchStateGlobal = 0x04,
    ConfigureNodeId = 0x11,
    ConfigureBitTiming = 0x13,
    ActivateBitTiming = 0x15,
    StoreConfiguration = 0x17,
    SwitchStateSelectiveVendorId = 0x40,
    SwitchStateSelectiveProductCode = 0x41,
    SwitchStateSelectiveRevisionNumber = 0x42,
    SwitchStateSelectiveSerialNumber = 0x43,
    SwitchStateSelectiveResponse = 0x44,
    IdentifyRemoteSlaveVendorId = 0x46,
    IdentifyRemoteSlaveProductCode = 0x47,
    IdentifyRemoteSlaveRevisionLow = 0x48,
    IdentifyRemoteSlaveRevisionHigh = 0x49,
    IdentifyRemoteSlaveSerialLow = 0x4A,
    IdentifyRemoteSlaveSerialHigh = 0x4B,
    IdentifyNonConfiguredRemoteSlave = 0x4C,
    IdentifySlave = 0x4F,              ///< response to identify remote slave and fastscan
    IdentifyNonConfiguredSlave = 0x50, ///< response to identify non-configured remote slave
    Fastscan = 0x51,
    InquireVendorId = 0x5A,
    InquireProductCode = 0x5B,
    InquireRevisionNumber = 0x5C,
    InquireSerialNumber = 0x5D,
    InquireNodeId = 0x5E,
};

/// The name of a service or response ("configure node-ID"), for messages.
std::string_view to_string(LssCommand cs);

/// The LSS states of a slave; the values are the mode byte of switch state global (7.4.2.1).
enum class LssState : std::uint8_t {
    Waiting = 0,
    Configuration = 1,
};

/// The four numbers of an LSS address, in the order of the identity object 0x1018 sub 1..4;
/// fastscan's LSSSub and LSSNext count in this order.
enum class LssPart : std::uint8_t {
    VendorId = 0,
    ProductCode = 1,
    RevisionNumber = 2,
    SerialNumber = 3,
};
inline constexpr std::size_t kLssPartCount = 4;
std::string_view to_string(LssPart part); ///< "vendor-ID", "product code", ...

/// The LSS address (EPOS2 FW spec 7.4): the identity object 0x1018 sub 1..4, unique per network.
struct LssAddress {
    std::uint32_t vendor_id = 0;
    std::uint32_t product_code = 0;
    std::uint32_t revision_number = 0;
    std::uint32_t serial_number = 0;

    std::uint32_t part(LssPart which) const;
    void set_part(LssPart which, std::uint32_t value);
    friend bool operator==(const LssAddress&, const LssAddress&) = default;
};
/// "vendor-ID 0x000000FB, product code 0x..., revision number 0x..., serial number 0x...".
std::string to_string(const LssAddress& address);

/// The "no node-ID" value that configure node-ID accepts and an unconfigured slave reports.
inline constexpr NodeId kLssUnconfiguredNodeId = 0xFF;
/// A node-ID a device can run with: 1..127 (0 and 0xFF mean "not configured", EPOS2 7.4).
bool is_configured_node_id(NodeId id);
/// What configure node-ID accepts: 1..127, or 0xFF to remove the node-ID (CiA 305).
bool is_lss_node_id(NodeId id);

/// The error codes of the confirmed configuration services (EPOS2 FW spec 7.4.2.3-7.4.2.6);
/// 255 means that the specific error byte carries a manufacturer-specific code.
inline constexpr std::uint8_t kLssSuccess = 0;
inline constexpr std::uint8_t kLssNodeIdOutOfRange = 1;
inline constexpr std::uint8_t kLssBitTimingNotSupported = 1;
inline constexpr std::uint8_t kLssStoreNotSupported = 1;
inline constexpr std::uint8_t kLssStorageAccessError = 2;
inline constexpr std::uint8_t kLssImplementationSpecificError = 255;

/// Table selector 0: the CiA bit timing table (CiA 301 / CiA 305, the EPOS2's CAN bit rate codes).
inline constexpr std::uint8_t kLssStandardBitTimingTable = 0;
/// Index → bit/s of the standard table; 0 at index 5, which is reserved.
inline constexpr std::array<std::uint32_t, 9> kLssBitTimingTable = {
    1'000'000, 800'000, 500'000, 250'000, 125'000, 0, 50'000, 20'000, 10'000};
/// The bit rate of a (table selector, table index) pair; nullopt for another table, the reserved
/// index 5 and indices past 8 (9, automatic bit rate detection, is not supported).
std::optional<std::uint32_t> lss_bit_rate(std::uint8_t table_selector, std::uint8_t table_index);
/// The index of `bit_rate` (bit/s) in the standard table; nullopt when it has none.
std::optional<std::uint8_t> lss_bit_timing_index(std::uint32_t bit_rate);

/// Fastscan's BitChecked value that restarts every non-configured slave's scan (CiA 305).
inline constexpr std::uint8_t kFastscanConfirm = 0x80;

/// The fields of a fastscan request (CiA 305): bits `bit_checked`..31 of `id_number` are compared
/// with the LSS address part `sub`; a slave that matched all 32 bits goes on with part `next`.
struct FastscanRequest {
    std::uint32_t id_number = 0;
    std::uint8_t bit_checked = kFastscanConfirm; ///< 0..31, or kFastscanConfirm
    LssPart sub = LssPart::VendorId;
    LssPart next = LssPart::VendorId;
    friend bool operator==(const FastscanRequest&, const FastscanRequest&) = default;
};

// Encoding.

/// An LSS frame on `cob_id`: `cs` in byte 0, `bytes` from byte 1 on, zeros after, DLC 8.
can::Frame lss_frame(std::uint32_t cob_id, LssCommand cs,
                     std::initializer_list<std::uint8_t> bytes = {});
/// An LSS frame carrying `value` (UNSIGNED32, little-endian) in bytes 1..4.
can::Frame lss_frame_u32(std::uint32_t cob_id, LssCommand cs, std::uint32_t value);
/// A fastscan request frame (master → slaves).
can::Frame lss_fastscan_frame(const FastscanRequest& request);

// Decoding.

/// The command specifier of `frame` if it is an LSS frame on `cob_id`: a standard data frame
/// with exactly 8 data bytes; nullopt for anything else, which LSS ignores.
std::optional<LssCommand> lss_command(const can::Frame& frame, std::uint32_t cob_id);
/// The UNSIGNED32 in bytes 1..4.
std::uint32_t lss_u32(const can::Frame& frame);
/// The UNSIGNED16 in bytes 1..2 (the switch delay of activate bit timing).
std::uint16_t lss_u16(const can::Frame& frame);
/// The fields of a fastscan frame; nullopt when BitChecked, LSSSub or LSSNext is out of range.
std::optional<FastscanRequest> lss_fastscan_request(const can::Frame& frame);

} // namespace eposp::canopen
