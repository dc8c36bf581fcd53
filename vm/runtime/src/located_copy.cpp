#include "located_copy.hpp"

#include <cstring>

namespace eposp::vm::detail {
namespace {

std::uint8_t bit_mask(const IoBinding& binding) {
    return static_cast<std::uint8_t>(1U << binding.bit);
}

} // namespace

std::uint32_t binding_size(const IoBinding& binding) {
    return binding.type == Scalar::Bool ? 1 : scalar_size(binding.type);
}

void copy_into_variable(std::span<const std::uint8_t> area, const IoBinding& binding,
                        std::span<std::uint8_t> memory) {
    if (binding.type == Scalar::Bool) {
        memory[binding.offset] = (area[binding.byte_address] >> binding.bit) & 1U;
    } else {
        std::memcpy(memory.data() + binding.offset, area.data() + binding.byte_address,
                    scalar_size(binding.type));
    }
}

void copy_into_area(std::span<std::uint8_t> area, const IoBinding& binding,
                    std::span<const std::uint8_t> memory) {
    if (binding.type == Scalar::Bool) {
        auto& byte = area[binding.byte_address];
        byte = memory[binding.offset] != 0 ? static_cast<std::uint8_t>(byte | bit_mask(binding))
                                           : static_cast<std::uint8_t>(byte & ~bit_mask(binding));
    } else {
        std::memcpy(area.data() + binding.byte_address, memory.data() + binding.offset,
                    scalar_size(binding.type));
    }
}

void clear_in_area(std::span<std::uint8_t> area, const IoBinding& binding) {
    if (binding.type == Scalar::Bool) {
        area[binding.byte_address] &= static_cast<std::uint8_t>(~bit_mask(binding));
    } else {
        std::memset(area.data() + binding.byte_address, 0, scalar_size(binding.type));
    }
}

} // namespace eposp::vm::detail
