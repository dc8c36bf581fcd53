#include "eposp/vm/native.hpp"

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace eposp::vm {

std::span<std::uint8_t> NativeArgs::memory(std::uint64_t address, std::uint32_t size) const {
    if (address < kNullGuardSize || address > memory_.size() || size > memory_.size() - address) {
        return {};
    }
    return memory_.subspan(address, size);
}

void NativeRegistry::add(std::string name, NativeSignature signature, NativeFunction function) {
    const auto [_, inserted] =
        entries_.emplace(std::move(name), Entry{std::move(signature), std::move(function)});
    if (!inserted) {
        throw std::logic_error("native function registered twice");
    }
}

void NativeRegistry::add_block(std::string name, std::vector<Scalar> fields,
                               NativeBlockFunction body) {
    auto layout = std::make_shared<const NativeBlockLayout>(fields);
    add(std::move(name), {.parameters = {Scalar::Ptr}, .instance = std::move(fields)},
        [layout, body = std::move(body)](NativeArgs& args) {
            NativeBlock block(args, *layout);
            if (!block.valid()) {
                args.fail("a native function block was called without its instance");
                return;
            }
            body(block);
        });
}

NativeBlockLayout::NativeBlockLayout(std::vector<Scalar> fields) : fields_(std::move(fields)) {
    std::uint32_t offset = 0;
    std::uint32_t align = 1;
    for (const Scalar field : fields_) {
        const std::uint32_t size = scalar_size(field);
        offset = (offset + size - 1) / size * size;
        offsets_.push_back(offset);
        offset += size;
        align = std::max(align, size);
    }
    size_ = std::max<std::uint32_t>((offset + align - 1) / align * align, 1);
}

const NativeRegistry::Entry* NativeRegistry::find(const std::string& name) const {
    const auto it = entries_.find(name);
    return it == entries_.end() ? nullptr : &it->second;
}

} // namespace eposp::vm
