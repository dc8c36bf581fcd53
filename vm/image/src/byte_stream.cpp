#include "byte_stream.hpp"

#include <algorithm>

namespace eposp::vm::detail {

void ByteWriter::string(std::string_view s) {
    u32(static_cast<std::uint32_t>(s.size()));
    raw({reinterpret_cast<const std::uint8_t*>(s.data()), s.size()});
}

void ByteWriter::raw(std::span<const std::uint8_t> data) {
    if (bytes_.size() - size_ < data.size()) {
        grow(data.size());
    }
    std::copy(data.begin(), data.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(size_));
    size_ += data.size();
}

void ByteWriter::patch_u32(std::size_t at, std::uint32_t v) {
    for (std::size_t i = 0; i < 4; ++i) {
        bytes_[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
    }
}

void ByteWriter::grow(std::size_t n) {
    bytes_.resize(std::max(2 * bytes_.size(), size_ + n + 256));
}

std::uint64_t ByteReader::get(int n) {
    if (failed()) {
        return 0;
    }
    if (remaining() < static_cast<std::size_t>(n)) {
        fail("truncated");
        return 0;
    }
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) {
        v |= static_cast<std::uint64_t>(data_[pos_ + i]) << (8 * i);
    }
    pos_ += static_cast<std::size_t>(n);
    return v;
}

std::span<const std::uint8_t> ByteReader::raw(std::size_t n) {
    if (failed()) {
        return {};
    }
    if (remaining() < n) {
        fail("truncated");
        return {};
    }
    auto out = data_.subspan(pos_, n);
    pos_ += n;
    return out;
}

std::string ByteReader::string() {
    const auto bytes = raw(u32());
    return {bytes.begin(), bytes.end()};
}

std::uint32_t ByteReader::count(std::size_t min_element_size) {
    const auto n = u32();
    if (!failed() && n > remaining() / min_element_size) {
        fail("element count " + std::to_string(n) + " larger than the data left");
        return 0;
    }
    return n;
}

void ByteReader::fail(std::string message) {
    if (!failed()) {
        error_ = std::move(message);
    }
}

} // namespace eposp::vm::detail
