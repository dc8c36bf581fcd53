// The argument block of a native call (image.hpp): its layout is part of the image format, laid
// out by codegen, checked by the verifier and read by the runtime's natives.

#include "eposp/vm/image.hpp"

namespace eposp::vm {

std::uint32_t argument_block_size(const NativeSignature& signature) {
    std::uint32_t end = signature.has_result ? scalar_size(signature.result) : 0;
    for (std::size_t i = 0; i < signature.parameters.size(); ++i) {
        end = parameter_offset(signature, i) + scalar_size(signature.parameters[i]);
    }
    return end;
}

std::uint32_t parameter_offset(const NativeSignature& signature, std::size_t index) {
    std::uint32_t offset = signature.has_result ? scalar_size(signature.result) : 0;
    for (std::size_t i = 0; i <= index && i < signature.parameters.size(); ++i) {
        const auto size = scalar_size(signature.parameters[i]);
        offset = (offset + size - 1) / size * size;
        if (i == index) {
            return offset;
        }
        offset += size;
    }
    return offset;
}

} // namespace eposp::vm
