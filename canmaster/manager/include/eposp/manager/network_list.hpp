#pragma once

#include "eposp/canopen/lss_protocol.hpp"
#include "eposp/canopen/nmt_protocol.hpp"
#include "eposp/canopen/value_codec.hpp"
#include "eposp/core/time.hpp"

#include <chrono>
#include <cstdint>
#include <vector>

namespace eposp::manager {

/// 0x1F81 Slave Assignment (CiA 302-2; EPOS P firmware specification 10.23, tables 25 and 26).
namespace assignment {
inline constexpr std::uint32_t kSlave = 1U << 0;     ///< an NMT slave, present in the network
inline constexpr std::uint32_t kBootSlave = 1U << 2; ///< may be configured and started
inline constexpr std::uint32_t kMandatory = 1U << 3; ///< must be present for the network to start
} // namespace assignment

/// 0x1F80 NMT Start-up (CiA 302-2; EPOS P 10.22, tables 23 and 24).
namespace nmt_startup {
inline constexpr std::uint32_t kMaster = 1U << 0;
inline constexpr std::uint32_t kStartAllNodes = 1U << 1;    ///< one "start remote node" to node 0
inline constexpr std::uint32_t kNotSelfStarting = 1U << 2;  ///< the application starts the master
inline constexpr std::uint32_t kDoNotStartSlaves = 1U << 3; ///< the application starts the slaves
} // namespace nmt_startup

/// One object write of a slave's configuration: what a concise DCF holds (CiA 302-3).
struct ConfigurationWrite {
    std::uint16_t index = 0;
    std::uint8_t sub_index = 0;
    canopen::Bytes value;
};

/// Everything the network list says of one slave (EPOS P 10.11, 10.20 - 10.29). An expected
/// value of 0 is not checked.
struct SlaveEntry {
    canopen::NodeId node_id = 0;
    std::uint32_t assignment = 0;         ///< 0x1F81
    std::uint32_t device_type = 0;        ///< 0x1F84, against the slave's 0x1000
    canopen::LssAddress identity;         ///< 0x1F85 - 0x1F88, against its 0x1018
    std::uint32_t configuration_date = 0; ///< 0x1F26, against its 0x1020 sub 1
    std::uint32_t configuration_time = 0; ///< 0x1F27, against its 0x1020 sub 2
    /// The consumer heartbeat time of 0x1016 for the slave; 0: no error control check.
    core::Duration heartbeat{};
    /// Written in order once the checks passed (the PDO set-up an axis needs, a concise DCF).
    std::vector<ConfigurationWrite> configuration;

    bool assigned() const { return (assignment & assignment::kSlave) != 0; }
    bool mandatory() const { return (assignment & assignment::kMandatory) != 0; }
    bool may_boot() const { return (assignment & assignment::kBootSlave) != 0; }
};

/// The network list of one port.
struct NetworkList {
    std::uint32_t nmt_startup = nmt_startup::kMaster | nmt_startup::kStartAllNodes |
                                nmt_startup::kNotSelfStarting; ///< 0x1F80, default 7
    /// 0x1F89: the time the slaves are given to boot before the manager accesses them.
    core::Duration boot_time = std::chrono::milliseconds(500);
    std::vector<SlaveEntry> slaves;
};

} // namespace eposp::manager
