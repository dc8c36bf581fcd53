#include "eposp/vm/program.hpp"

#include "eposp/vm/image_format.hpp"
#include "eposp/vm/verifier.hpp"

namespace eposp::vm {

core::Result<Program> link(Image image, const NativeRegistry& natives) {
    if (auto defect = verify(image)) {
        return *defect;
    }
    std::vector<const NativeFunction*> bound;
    for (const auto& import : image.imports) {
        const auto* entry = natives.find(import.name);
        if (entry == nullptr) {
            return core::Error{"native function " + import.name + " is not available"};
        }
        if (entry->signature != import.signature) {
            return core::Error{"native function " + import.name +
                               " has a different signature than the program expects"};
        }
        bound.push_back(&entry->function);
    }
    return Program(std::move(image), std::move(bound));
}

core::Result<Program> load_program(std::span<const std::uint8_t> bytes,
                                   const NativeRegistry& natives) {
    auto image = read_image(bytes);
    if (!image) {
        return core::Error{image.error()};
    }
    return link(std::move(*image), natives);
}

} // namespace eposp::vm
