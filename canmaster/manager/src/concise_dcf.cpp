#include "eposp/manager/concise_dcf.hpp"

#include <fmt/format.h>

namespace eposp::manager {
namespace {

template <typename T>
void append(std::vector<std::uint8_t>& out, T value) {
    for (std::size_t byte = 0; byte < sizeof(T); ++byte) {
        out.push_back(static_cast<std::uint8_t>(value >> (8 * byte)));
    }
}

// Reads little-endian values front to back, remembering where it is for the error message.
class Cursor {
public:
    explicit Cursor(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    template <typename T>
    bool read(T& value) {
        if (bytes_.size() - at_ < sizeof(T)) {
            return false;
        }
        value = 0;
        for (std::size_t byte = 0; byte < sizeof(T); ++byte) {
            value = static_cast<T>(value | T{bytes_[at_ + byte]} << (8 * byte));
        }
        at_ += sizeof(T);
        return true;
    }
    bool take(std::size_t size, canopen::Bytes& out) {
        if (bytes_.size() - at_ < size) {
            return false;
        }
        out.assign(bytes_.begin() + static_cast<std::ptrdiff_t>(at_),
                   bytes_.begin() + static_cast<std::ptrdiff_t>(at_ + size));
        at_ += size;
        return true;
    }
    std::size_t at() const { return at_; }
    std::size_t left() const { return bytes_.size() - at_; }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t at_ = 0;
};

} // namespace

std::vector<std::uint8_t> encode_concise_dcf(std::span<const ConfigurationWrite> writes) {
    std::vector<std::uint8_t> out;
    append(out, static_cast<std::uint32_t>(writes.size()));
    for (const ConfigurationWrite& write : writes) {
        append(out, write.index);
        append(out, write.sub_index);
        append(out, static_cast<std::uint32_t>(write.value.size()));
        out.insert(out.end(), write.value.begin(), write.value.end());
    }
    return out;
}

core::Result<std::vector<ConfigurationWrite>> decode_concise_dcf(std::span<const std::uint8_t> bytes) {
    Cursor in(bytes);
    std::uint32_t count = 0;
    if (!in.read(count)) {
        return core::Error{"a concise DCF starts with its number of entries (4 bytes)"};
    }
    std::vector<ConfigurationWrite> writes;
    for (std::uint32_t entry = 1; entry <= count; ++entry) {
        const std::size_t start = in.at();
        ConfigurationWrite write;
        std::uint32_t size = 0;
        if (!in.read(write.index) || !in.read(write.sub_index) || !in.read(size)) {
            return core::Error{fmt::format("entry {} of {} is cut off at byte {}", entry, count,
                                           start)};
        }
        if (size == 0 || !in.take(size, write.value)) {
            return core::Error{fmt::format("entry {} of {} (0x{:04X} sub {}) at byte {}: {} bytes "
                                           "of data, {} left",
                                           entry, count, write.index, write.sub_index, start, size,
                                           in.left())};
        }
        writes.push_back(std::move(write));
    }
    if (in.left() != 0) {
        return core::Error{fmt::format("{} bytes after the last of its {} entries, at byte {}",
                                       in.left(), count, in.at())};
    }
    return writes;
}

} // namespace eposp::manager
