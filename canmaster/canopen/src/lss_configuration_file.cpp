#include "lss_configuration_file.hpp"

#include "eposp/core/durable_file.hpp"
#include "parameter_file.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>
#include <string_view>

namespace eposp::canopen {
namespace {

constexpr std::string_view kMagic = "EPOSPLSS";
constexpr std::size_t kNodeIdAt = kMagic.size();
constexpr std::size_t kBitRateAt = kNodeIdAt + 1;
constexpr std::size_t kCrcAt = kBitRateAt + 4;
constexpr std::size_t kFileSize = kCrcAt + 4;

} // namespace

LssStoreResult LssConfigurationFile::store(const LssConfiguration& configuration) const {
    Bytes content(kMagic.begin(), kMagic.end());
    content.push_back(configuration.node_id);
    const Bytes bit_rate = encode(configuration.bit_rate);
    content.insert(content.end(), bit_rate.begin(), bit_rate.end());
    const Bytes crc = encode(crc32(content));
    content.insert(content.end(), crc.begin(), crc.end());
    return core::write_file_durably(path_, content) ? LssStoreResult::StorageAccessError
                                              : LssStoreResult::Stored;
}

core::Result<std::optional<LssConfiguration>> LssConfigurationFile::load() const {
    auto content = core::read_whole_file(path_);
    if (!content) {
        return core::Error{content.error()};
    }
    if (!content->has_value()) {
        return std::optional<LssConfiguration>{};
    }
    const Bytes& bytes = **content;
    const std::span<const std::uint8_t> all(bytes);
    if (bytes.size() != kFileSize || !std::equal(kMagic.begin(), kMagic.end(), bytes.begin()) ||
        decode<std::uint32_t>(all.subspan(kCrcAt, 4)) != crc32(all.first(kCrcAt))) {
        return core::Error{
            fmt::format("{}: the stored LSS configuration is damaged", path_.string())};
    }
    return std::optional<LssConfiguration>{LssConfiguration{
        .node_id = bytes[kNodeIdAt],
        .bit_rate = decode<std::uint32_t>(all.subspan(kBitRateAt, 4)),
    }};
}

} // namespace eposp::canopen
