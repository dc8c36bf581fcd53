#include "parameter_file.hpp"

#include <algorithm>
#include <array>
#include <boost/crc.hpp>
#include <fmt/format.h>
#include <optional>

namespace eposp::canopen {
namespace {

constexpr std::array<std::uint8_t, 8> kMagic = {'E', 'P', 'O', 'S', 'P', 'P', 'A', 'R'};
constexpr std::uint16_t kFormatVersion = 1;

void put(Bytes& out, std::uint64_t value, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
        out.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
    }
}

// Reads fields front to back; every read checks that the bytes are there.
class Reader {
public:
    explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    std::optional<std::uint64_t> take(std::size_t size) {
        if (bytes_.size() - position_ < size) {
            return std::nullopt;
        }
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < size; ++i) {
            value |= std::uint64_t{bytes_[position_ + i]} << (8 * i);
        }
        position_ += size;
        return value;
    }
    std::optional<std::span<const std::uint8_t>> take_bytes(std::size_t size) {
        if (bytes_.size() - position_ < size) {
            return std::nullopt;
        }
        const auto span = bytes_.subspan(position_, size);
        position_ += size;
        return span;
    }
    bool at_end() const { return position_ == bytes_.size(); }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t position_ = 0;
};

core::Error damaged(std::string_view why) {
    return core::Error{fmt::format("the parameter store is damaged: {}", why)};
}

} // namespace

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
    boost::crc_32_type crc;
    crc.process_bytes(bytes.data(), bytes.size());
    return crc.checksum();
}

Bytes serialize(const ParameterFile& file) {
    Bytes out(kMagic.begin(), kMagic.end());
    put(out, kFormatVersion, 2);
    put(out, file.layout_id, 4);
    put(out, file.entries.size(), 4);
    for (const auto& entry : file.entries) {
        put(out, entry.index, 2);
        put(out, entry.sub_index, 1);
        put(out, entry.value.size(), 4);
        out.insert(out.end(), entry.value.begin(), entry.value.end());
    }
    put(out, crc32(out), 4);
    return out;
}

core::Result<ParameterFile> parse_parameter_file(std::span<const std::uint8_t> bytes) {
    constexpr std::size_t kCrcSize = 4;
    if (bytes.size() < kMagic.size() + kCrcSize) {
        return damaged("too short");
    }
    const auto body = bytes.first(bytes.size() - kCrcSize);
    if (*Reader(bytes.last(kCrcSize)).take(kCrcSize) != crc32(body)) {
        return damaged("checksum mismatch");
    }
    if (!std::equal(kMagic.begin(), kMagic.end(), body.begin())) {
        return damaged("not a parameter store file");
    }
    Reader reader(body.subspan(kMagic.size()));
    const auto version = reader.take(2);
    if (version != kFormatVersion) {
        return damaged("unknown format version");
    }
    const auto layout_id = reader.take(4);
    const auto count = reader.take(4);
    if (!layout_id || !count) {
        return damaged("truncated header");
    }
    ParameterFile file;
    file.layout_id = static_cast<std::uint32_t>(*layout_id);
    for (std::uint64_t i = 0; i < *count; ++i) {
        const auto index = reader.take(2);
        const auto sub_index = reader.take(1);
        const auto length = reader.take(4);
        const auto value = length ? reader.take_bytes(*length) : std::nullopt;
        if (!index || !sub_index || !value) {
            return damaged(fmt::format("entry {} is truncated", i + 1));
        }
        file.entries.push_back({static_cast<std::uint16_t>(*index),
                                static_cast<std::uint8_t>(*sub_index),
                                Bytes(value->begin(), value->end())});
    }
    if (!reader.at_end()) {
        return damaged("bytes after the last entry");
    }
    return file;
}

} // namespace eposp::canopen
