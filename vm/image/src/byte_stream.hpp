#pragma once

// Little-endian encoding of the image's fields. The reader never trusts a length: every read is
// checked against what is left, and a failed read latches an error instead of throwing, so a
// section decoder can read straight through and check once at its end.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace eposp::vm::detail {

// Writes through a pointer into bytes already allocated, the fields of fixed size inline: a large
// image has millions of fields, and a push_back a byte reloads the vector's end after each store.
class ByteWriter {
public:
    void u8(std::uint8_t v) { put<1>(v); }
    void u16(std::uint16_t v) { put<2>(v); }
    void u32(std::uint32_t v) { put<4>(v); }
    void u64(std::uint64_t v) { put<8>(v); }
    void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
    void string(std::string_view s);
    void raw(std::span<const std::uint8_t> data);
    /// Overwrites 4 bytes at `at` (a length written after its contents).
    void patch_u32(std::size_t at, std::uint32_t v);

    std::size_t size() const { return size_; }
    /// What has been written.
    std::vector<std::uint8_t>& bytes() {
        bytes_.resize(size_);
        return bytes_;
    }

private:
    template <std::size_t N>
    void put(std::uint64_t v) {
        if (bytes_.size() - size_ < N) {
            grow(N);
        }
        std::uint8_t* at = bytes_.data() + size_;
        for (std::size_t i = 0; i < N; ++i) {
            at[i] = static_cast<std::uint8_t>(v >> (8 * i));
        }
        size_ += N;
    }
    /// Room for `n` bytes more.
    void grow(std::size_t n);

    std::vector<std::uint8_t> bytes_; // written up to size_, then room
    std::size_t size_ = 0;
};

class ByteReader {
public:
    explicit ByteReader(std::span<const std::uint8_t> data) : data_(data) {}

    std::uint8_t u8() { return static_cast<std::uint8_t>(get(1)); }
    std::uint16_t u16() { return static_cast<std::uint16_t>(get(2)); }
    std::uint32_t u32() { return static_cast<std::uint32_t>(get(4)); }
    std::uint64_t u64() { return get(8); }
    std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
    std::string string();
    /// `n` bytes, or an empty span (and the error latched) if fewer are left.
    std::span<const std::uint8_t> raw(std::size_t n);
    /// An element count, refused if the remaining bytes cannot hold that many elements of at
    /// least `min_element_size` bytes (so a forged count cannot make us allocate gigabytes).
    std::uint32_t count(std::size_t min_element_size);
    /// An enumerator, refused if its value is above `last`.
    template <typename Enum>
    Enum enumerator(Enum last, std::string_view what) {
        const auto v = u8();
        if (v > static_cast<std::uint8_t>(last)) {
            fail("invalid " + std::string(what) + " " + std::to_string(v));
        }
        return static_cast<Enum>(v);
    }

    void fail(std::string message);
    bool failed() const { return !error_.empty(); }
    const std::string& error() const { return error_; }
    std::size_t remaining() const { return data_.size() - pos_; }

private:
    std::uint64_t get(int n);

    std::span<const std::uint8_t> data_;
    std::size_t pos_ = 0;
    std::string error_;
};

} // namespace eposp::vm::detail
