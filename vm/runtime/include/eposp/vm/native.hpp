#pragma once

#include "eposp/vm/image.hpp"
#include "eposp/vm/native_values.hpp"
#include "eposp/vm/task_state.hpp"

#include <cstdint>
#include <cstring>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace eposp::vm {

/// Where a native call runs, for NativeArgs::call_site(): filled by both engines at every call
/// (a few stores), read only when a host asks.
struct NativeCallContext {
    const Image* image = nullptr;
    const Activation* calls = nullptr; ///< the task's callers, calls[0] the outermost
    std::uint32_t depth = 0;           ///< how many of them
    std::uint32_t instruction = 0;     ///< the CallNative being executed
};

/// What a native function sees of one call: its argument block (laid out as NativeSignature
/// says) and checked access to VM memory for pointer arguments (strings, FB instances).
/// The accessors of pointer arguments (text, any, array) fail() the call and return an empty
/// value when the pointer does not point to what the signature says (only a corrupt image does
/// that): the task stops with a run-time error when the function returns.
class NativeArgs {
public:
    NativeArgs(std::uint8_t* block, const NativeSignature& signature,
               std::span<std::uint8_t> memory, const NativeCallContext* context = nullptr)
        : block_(block), signature_(signature), memory_(memory), context_(context) {}

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

    /// The text of the STRING parameter `index` (a Ptr).
    std::string text(std::size_t index);
    /// The text of the WSTRING parameter `index` (a Ptr), as UTF-8.
    std::string wide_text(std::size_t index);
    /// The value of the ANY input whose pointer is parameter `index` (its descriptor, a U32,
    /// is parameter `index + 1`).
    NativeValue any(std::size_t index);
    /// The ARRAY[*] whose reference is parameter `index` (its element descriptor, a U32, is
    /// parameter `index + 1`).
    NativeArray array(std::size_t index);

    /// The POU and line of this call, as a run-time error there would name them; empty when
    /// the engine gave no context (a NativeArgs made by hand). Computed when asked: call it on
    /// the failure path, not at every call.
    NativeCallSite call_site() const;
    /// The call sites of the POUs that called the one making this call, the innermost first
    /// and the task's program last (a call copied in place counts as a call).
    std::vector<NativeCallSite> callers() const;

    /// Stops the calling task with this reason (allocates: only on the error path).
    void fail(std::string reason) { failure_ = std::move(reason); }
    bool failed() const { return !failure_.empty(); }
    const std::string& failure() const { return failure_; }

private:
    std::uint8_t* block_;
    const NativeSignature& signature_;
    std::span<std::uint8_t> memory_;
    const NativeCallContext* context_;
    std::string failure_;
};

using NativeFunction = std::function<void(NativeArgs&)>;

/// Where the fields of a native function block's instance are: each field, in declaration order,
/// at the next offset aligned to its size, as the compiler lays out an instance whose fields are
/// all elementary or VAR_IN_OUT (a pointer).
class NativeBlockLayout {
public:
    explicit NativeBlockLayout(std::vector<Scalar> fields);
    const std::vector<Scalar>& fields() const { return fields_; }
    std::uint32_t offset(std::size_t field) const { return offsets_[field]; }
    std::uint32_t size() const { return size_; }

private:
    std::vector<Scalar> fields_;
    std::vector<std::uint32_t> offsets_;
    std::uint32_t size_ = 0;
};

/// The instance of a native function block as its C++ body sees it during one call: its fields
/// read and written in place, so the block's state lives in the instance (its VAR section) and
/// is initialised, retained and watched like any FB's.
class NativeBlock {
public:
    /// The instance the call's argument points to.
    NativeBlock(NativeArgs& args, const NativeBlockLayout& layout)
        : args_(args), layout_(layout),
          instance_(args.memory(args.get<std::uint64_t>(0), layout.size())) {}

    /// False when the argument points outside VM memory (only a corrupt image does that).
    bool valid() const { return !instance_.empty(); }
    template <typename T>
    T get(std::size_t field) const {
        T value;
        std::memcpy(&value, instance_.data() + layout_.offset(field), sizeof(T));
        return value;
    }
    template <typename T>
    void set(std::size_t field, T value) {
        std::memcpy(instance_.data() + layout_.offset(field), &value, sizeof(T));
    }
    /// Sets `field` to zero (FALSE, 0).
    void clear(std::size_t field) {
        std::memset(instance_.data() + layout_.offset(field), 0,
                    scalar_size(layout_.fields()[field]));
    }
    /// `size` bytes of what the VAR_IN_OUT `field` refers to; empty if it refers to nothing.
    std::span<std::uint8_t> referenced(std::size_t field, std::uint32_t size) const {
        return args_.memory(get<std::uint64_t>(field), size);
    }
    NativeArgs& args() { return args_; }

private:
    NativeArgs& args_;
    const NativeBlockLayout& layout_;
    std::span<std::uint8_t> instance_;
};

using NativeBlockFunction = std::function<void(NativeBlock&)>;

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
    /// A native function block: the body of the FUNCTION_BLOCK `name` declared without
    /// statements in a linked library, its instance laid out as `fields` say.
    void add_block(std::string name, std::vector<Scalar> fields, NativeBlockFunction body);
    const Entry* find(const std::string& name) const;

private:
    std::map<std::string, Entry, std::less<>> entries_;
};

} // namespace eposp::vm
