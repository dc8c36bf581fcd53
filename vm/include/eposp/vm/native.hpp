#pragma once

#include "eposp/vm/image.hpp"

#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <span>
#include <string>

namespace eposp::vm {

/// What a native function sees of one call: its argument block (laid out as NativeSignature
/// says) and checked access to VM memory for pointer arguments (strings, FB instances).
class NativeArgs {
public:
    NativeArgs(std::uint8_t* block, const NativeSignature& signature,
               std::span<std::uint8_t> memory)
        : block_(block), signature_(signature), memory_(memory) {}

    template <typename T>
    T get(std::size_t index) const {
        T value;
        std::memcpy(&value, block_ + parameter_offset(signature_, index), sizeof(T));
        return value;
    }
    template <typename T>
    void set_result(T value) {
        std::memcpy(block_, &value, sizeof(T));
    }
    /// `size` bytes of VM memory at `address`; empty if that is NULL or outside the memory.
    std::span<std::uint8_t> memory(std::uint64_t address, std::uint32_t size) const;

    /// Stops the calling task with this reason (allocates: only on the error path).
    void fail(std::string reason) { failure_ = std::move(reason); }
    bool failed() const { return !failure_.empty(); }
    const std::string& failure() const { return failure_; }

private:
    std::uint8_t* block_;
    const NativeSignature& signature_;
    std::span<std::uint8_t> memory_;
    std::string failure_;
};

using NativeFunction = std::function<void(NativeArgs&)>;

/// The host functions a program may import, by name; the device, the standard library and
/// later plcopen's MC_* blocks fill it. A native FB is a native function whose first parameter
/// is a pointer to its instance.
class NativeRegistry {
public:
    struct Entry {
        NativeSignature signature;
        NativeFunction function;
    };

    /// Registering a name twice is a programming error.
    void add(std::string name, NativeSignature signature, NativeFunction function);
    const Entry* find(const std::string& name) const;

private:
    std::map<std::string, Entry, std::less<>> entries_;
};

} // namespace eposp::vm
