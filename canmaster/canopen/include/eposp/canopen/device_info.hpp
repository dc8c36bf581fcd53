#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace eposp::canopen {

/// The bit rates an EDS names in [DeviceInfo] (BaudRate_<kbit/s>=1, CiA 306 4.4).
inline constexpr std::array<std::uint16_t, 8> kEdsBaudRatesKbit = {10,  20,  50,  125,
                                                                   250, 500, 800, 1000};

/// [FileInfo] and [Comments] of an EDS (CiA 306 4.3, 4.5). Dates and times are text the caller
/// gives, as CiA 306 writes them ("hh:mm(AM|PM)", "mm-dd-yyyy"): no component reads the clock.
struct EdsFileInfo {
    std::string file_name;
    std::uint8_t file_version = 1;
    std::uint8_t file_revision = 0;
    std::string eds_version = "4.0";
    std::string description;
    std::string creation_time;
    std::string creation_date;
    std::string created_by;
    std::string modification_time;
    std::string modification_date;
    std::string modified_by;
    std::vector<std::string> comments; ///< the lines of [Comments]

    bool operator==(const EdsFileInfo&) const = default;
};

/// What an EDS says about the device beyond its objects: [FileInfo], [DeviceInfo] (CiA 306 4.4)
/// and [DummyUsage] (4.5.3). NrOfRxPDO / NrOfTxPDO are not here: an export counts the PDO
/// communication objects of the dictionary.
struct DeviceInfo {
    EdsFileInfo file;
    std::string vendor_name;
    std::uint32_t vendor_number = 0;
    std::string product_name;
    std::uint32_t product_number = 0;
    std::uint32_t revision_number = 0;
    std::string order_code;
    /// Of the rates CiA 306 lists: 10, 20, 50, 125, 250, 500, 800, 1000 kbit/s.
    std::set<std::uint16_t> baud_rates_kbit;
    /// The same in bit/s, as NodeConfig::bit_rates takes them.
    std::set<std::uint32_t> bit_rates() const;
    bool simple_boot_up_master = false;
    bool simple_boot_up_slave = false;
    std::uint8_t granularity = 8; ///< the mapping granularity in bits (0: no mapping)
    std::uint8_t dynamic_channels_supported = 0;
    bool group_messaging = false;
    bool lss_supported = false;
    /// The data type indices (0x0001..0x0007) the device accepts as dummy entries in a mapping.
    std::set<std::uint16_t> dummy_usage;

    bool operator==(const DeviceInfo&) const = default;
};

} // namespace eposp::canopen
