#include "eposp/vm/program.hpp"

#include "eposp/vm/image_format.hpp"
#include "eposp/vm/verifier.hpp"
#include "jit/compiled_code.hpp"

#include <cstdlib>
#include <string_view>

namespace eposp::vm {

Engine default_engine() {
    static const Engine engine = [] {
        const char* chosen = std::getenv("EPOSP_VM_ENGINE");
        return chosen != nullptr && std::string_view(chosen) == "interpreter" ? Engine::Interpreter
                                                                              : Engine::Compiled;
    }();
    return engine;
}

core::Result<Program> link(Image image, const NativeRegistry& natives, Engine engine) {
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
    auto compiled = engine == Engine::Compiled ? jit::compile(image) : nullptr;
    return Program(std::move(image), std::move(bound), std::move(compiled));
}

core::Result<Program> load_program(std::span<const std::uint8_t> bytes,
                                   const NativeRegistry& natives, Engine engine) {
    auto image = read_image(bytes);
    if (!image) {
        return core::Error{image.error()};
    }
    return link(std::move(*image), natives, engine);
}

} // namespace eposp::vm
