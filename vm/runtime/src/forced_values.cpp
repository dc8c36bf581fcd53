#include "eposp/vm/forced_values.hpp"

#include <algorithm>

namespace eposp::vm {

void ForcedValues::force(std::string path, std::uint32_t offset, std::vector<std::uint8_t> bytes) {
    release(offset);
    forced_.push_back({std::move(path), offset, std::move(bytes)});
}

bool ForcedValues::release(std::uint32_t offset) {
    return std::erase_if(forced_, [offset](const Forced& f) { return f.offset == offset; }) > 0;
}

void ForcedValues::apply(std::span<std::uint8_t> memory) const {
    for (const Forced& f : forced_) {
        std::copy(f.bytes.begin(), f.bytes.end(), memory.begin() + f.offset);
    }
}

} // namespace eposp::vm
