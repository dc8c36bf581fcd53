#pragma once

#include "eposp/canopen/lss_slave.hpp"
#include "eposp/core/result.hpp"

#include <filesystem>
#include <optional>

namespace eposp::canopen {

/// The non-volatile memory behind LSS store configuration (CiA 305; EPOS2 FW spec 7.4.2.6):
/// the node-ID and bit rate that a node starts with, in a file of their own (replaced
/// atomically), so that a restore of the default parameters (0x1011) does not take the node's
/// node-ID away.
///
/// Little-endian: the magic "EPOSPLSS", the node-ID (UNSIGNED8), the bit rate (UNSIGNED32, bit/s)
/// and a CRC-32 of everything before it.
class LssConfigurationFile {
public:
    explicit LssConfigurationFile(std::filesystem::path path) : path_(std::move(path)) {}

    LssStoreResult store(const LssConfiguration& configuration) const;
    /// What was stored; nullopt when nothing is; an error naming the file when it is damaged.
    core::Result<std::optional<LssConfiguration>> load() const;

    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

} // namespace eposp::canopen
