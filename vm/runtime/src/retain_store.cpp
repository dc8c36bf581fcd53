#include "eposp/vm/retain_store.hpp"

#include "eposp/core/durable_file.hpp"

#include <algorithm>
#include <boost/crc.hpp>
#include <cstring>
#include <fmt/format.h>

namespace eposp::vm {
namespace {

// File layout, little-endian: magic "EPRT", version u16, reserved u16, identity u32, payload
// size u32, the payload (the retain ranges in image order), CRC-32 u32 of all that precedes it.
constexpr std::array<std::uint8_t, 4> kMagic{'E', 'P', 'R', 'T'};
constexpr std::uint16_t kFormatVersion = 1;
constexpr std::size_t kHeaderSize = 16;
constexpr std::size_t kTrailerSize = 4;

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int byte = 0; byte < 4; ++byte) {
        out.push_back(static_cast<std::uint8_t>(value >> (8 * byte)));
    }
}

std::uint32_t get_u32(std::span<const std::uint8_t> bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int byte = 3; byte >= 0; --byte) {
        value = (value << 8) | bytes[at + static_cast<std::size_t>(byte)];
    }
    return value;
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
    boost::crc_32_type crc;
    crc.process_bytes(bytes.data(), bytes.size());
    return crc.checksum();
}

// Whether every retain range lies inside memory (a verified image guarantees it for static
// data; the check keeps a bad call from writing outside).
bool ranges_fit(const Image& image, std::size_t memory_size) {
    return std::all_of(image.retain.begin(), image.retain.end(), [&](const RetainRange& range) {
        return std::size_t{range.offset} + range.size <= memory_size;
    });
}

} // namespace

std::uint32_t retain_size(const Image& image) {
    std::uint32_t size = 0;
    for (const RetainRange& range : image.retain) {
        size += range.size;
    }
    return size;
}

std::uint32_t retain_identity(const Image& image) {
    boost::crc_32_type crc;
    const auto add = [&crc](const auto& value) {
        crc.process_bytes(&value, sizeof value);
    };
    const auto add_text = [&crc, &add](const std::string& text) {
        add(text.size());
        crc.process_bytes(text.data(), text.size());
    };
    add(image.static_size);
    for (const RetainRange& range : image.retain) {
        add(range.offset);
        add(range.size);
    }
    for (const Symbol& symbol : image.symbols) {
        add_text(symbol.path);
        add(symbol.offset);
        add(symbol.type);
    }
    for (const TypeDescriptor& type : image.types) {
        add_text(type.name);
        add(type.kind);
        add(type.size);
        for (const TypeField& field : type.fields) {
            add_text(field.name);
            add(field.type);
            add(field.offset);
        }
    }
    return crc.checksum();
}

RetainStore::RetainStore(std::filesystem::path file, std::uint32_t capacity)
    : file_(std::move(file)), capacity_(capacity) {}

std::optional<core::Error> RetainStore::check_capacity(const Image& image) const {
    const std::uint32_t needed = retain_size(image);
    if (needed > capacity_) {
        return core::Error{fmt::format(
            "the program declares {} bytes of RETAIN variables, the controller holds {}", needed,
            capacity_)};
    }
    return std::nullopt;
}

std::optional<core::Error> RetainStore::save(const Image& image,
                                             std::span<const std::uint8_t> memory) const {
    if (!ranges_fit(image, memory.size())) {
        return core::Error{"retain ranges outside the program's memory"};
    }
    std::vector<std::uint8_t> content(kMagic.begin(), kMagic.end());
    content.push_back(static_cast<std::uint8_t>(kFormatVersion));
    content.push_back(static_cast<std::uint8_t>(kFormatVersion >> 8));
    content.insert(content.end(), {0, 0});
    put_u32(content, retain_identity(image));
    put_u32(content, retain_size(image));
    for (const RetainRange& range : image.retain) {
        const auto bytes = memory.subspan(range.offset, range.size);
        content.insert(content.end(), bytes.begin(), bytes.end());
    }
    put_u32(content, crc32(content));
    return core::write_file_durably(file_, content);
}

RetainRestore RetainStore::restore(const Image& image, std::span<std::uint8_t> memory) const {
    const auto read = core::read_whole_file(file_);
    if (!read) {
        return {RetainOutcome::Corrupt, read.error()};
    }
    if (!*read) {
        return {RetainOutcome::NoStore, {}};
    }
    const std::span<const std::uint8_t> content = **read;
    if (content.size() < kHeaderSize + kTrailerSize ||
        !std::equal(kMagic.begin(), kMagic.end(), content.begin())) {
        return {RetainOutcome::Corrupt, "not a retain store"};
    }
    const std::size_t payload_size = get_u32(content, 12);
    if (content.size() != kHeaderSize + payload_size + kTrailerSize ||
        get_u32(content, kHeaderSize + payload_size) !=
            crc32(content.first(kHeaderSize + payload_size))) {
        return {RetainOutcome::Corrupt, "retain store checksum mismatch"};
    }
    if (content[4] != kFormatVersion || content[5] != 0) {
        return {RetainOutcome::Corrupt, "retain store of an unknown format version"};
    }
    if (get_u32(content, 8) != retain_identity(image) || payload_size != retain_size(image)) {
        return {RetainOutcome::OtherProgram,
                "retain store written by a program with another variable layout"};
    }
    if (!ranges_fit(image, memory.size())) {
        return {RetainOutcome::Corrupt, "retain ranges outside the program's memory"};
    }
    std::size_t at = kHeaderSize;
    for (const RetainRange& range : image.retain) {
        std::memcpy(memory.data() + range.offset, content.data() + at, range.size);
        at += range.size;
    }
    return {RetainOutcome::Restored, {}};
}

} // namespace eposp::vm
