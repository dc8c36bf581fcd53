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

class ByteWriter {
public:
    void u8(std::uint8_t v) { bytes_.push_back(v); }
    void u16(std::uint16_t v) { put(v, 2); }
    void u32(std::uint32_t v) { put(v, 4); }
    void u64(std::uint64_t v) { put(v, 8); }
    void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
    void string(std::string_view s);
    void raw(std::span<const std::uint8_t> data) {
        bytes_.insert(bytes_.end(), data.begin(), data.end());
    }
    /// Overwrites 4 bytes at `at` (a length written after its contents).
    void patch_u32(std::size_t at, std::uint32_t v);

    std::size_t size() const { return bytes_.size(); }
    std::vector<std::uint8_t>& bytes() { return bytes_; }

private:
    void put(std::uint64_t v, int n);
    std::vector<std::uint8_t> bytes_;
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
