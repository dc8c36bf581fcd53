#pragma once

#include "eposp/core/result.hpp"
#include "eposp/vm/image.hpp"
#include "eposp/vm/native.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace eposp::vm {

/// A verified image with its imports bound to host functions: the only thing the interpreter
/// runs. Made by link or load_program, so an unverified image cannot reach the interpreter.
class Program {
public:
    const Image& image() const { return image_; }
    const NativeFunction& native(std::uint32_t import) const { return *natives_[import]; }

private:
    friend core::Result<Program> link(Image image, const NativeRegistry& natives);
    Program(Image image, std::vector<const NativeFunction*> natives)
        : image_(std::move(image)), natives_(std::move(natives)) {}

    Image image_;
    std::vector<const NativeFunction*> natives_;
};

/// Verifies `image` and binds each import to the registry entry of the same name and
/// signature; the registry must outlive the program.
core::Result<Program> link(Image image, const NativeRegistry& natives);

/// read_image, then link: from the bytes of a file to something that can run.
core::Result<Program> load_program(std::span<const std::uint8_t> bytes,
                                   const NativeRegistry& natives);

} // namespace eposp::vm
